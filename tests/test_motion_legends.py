"""The motion figure's legends, each under its plot as laid out: the run's, the steady turn's and the stall's below
their abscissa's numbers and name, clear of the other plot and inside the figure, in every language and with a long
name of an axis; the plots as tall as the figure makes them without legends; and the stall's moments written as a
textbook writes them, M with its letter as a subscript (Mr, Md, Mt; Mс, Mд, Mт), where the words beside them can be
set in mathtext (not in Chinese: mathtext's fonts have no CJK glyphs, and the labels stay plain there)."""

from __future__ import annotations

import logging
import re
import tomllib
import warnings

import pytest
from test_motion_plots import BRAKE_AT, BRAKE_TORQUE, braked_dynamics

from graphplan.locale import strings
from graphplan.report.motion_plots import motion_figure, motion_plot
from graphplan.report.plot_style import LEGEND_GAP, settings

matplotlib = pytest.importorskip("matplotlib")

LOCALES = ("en", "ru", "zh")
# Each case: the figure's height as the module sets it before its legends (inches), the plots laid out in it.
CASES = {"steady": 8.0, "braked": 7.75, "never starts": 4.5}
# The subscripts of the resisting moment, the motor's and the brake's, as the locales' textbooks write them.
SUBSCRIPTS = {"en": {"motion_resisting": "r", "motion_motor_torque": "d", "motion_motor_torque_at_rest": "d"},
              "ru": {"motion_resisting": "с", "motion_motor_torque": "д", "motion_motor_torque_at_rest": "д"}}
BRAKED_SUBSCRIPTS = {"en": ("r", "t"), "ru": ("с", "т")}
# The tallest figure the notes show at its size: an A4 page's 297 mm less its margins and a caption.
NOTE_FIGURE_HEIGHT_MM = 230.0


def _dynamics(case: str, locale: str):
    from graphplan.machine_dynamics import MachineDynamics
    from graphplan.scene import load
    from graphplan.starters import starter

    if case == "braked":
        # 150 N·m against Mr ≥ 100 N·m, and from t = 0.5 s a brake of 80 N·m: it runs up, then stalls 386° on.
        return braked_dynamics(f"brake = {{ torque = {BRAKE_TORQUE}, at = {BRAKE_AT} }}\n")
    tables = tomllib.loads(starter("flywheel", locale))
    if case == "never starts":
        # The press's motor cut to 300 W: 20 N·m at rest against 35 N·m, the stall's plot alone.
        tables["dynamics"]["motor"] = {**tables["dynamics"]["motor"], "power": 300.0}
    return MachineDynamics(load(tables))


def _figure(case: str, locale: str, text=None):
    dynamics = _dynamics(case, locale)
    flywheel = None if dynamics.flywheel is None else (dynamics.model.coordinate, dynamics.flywheel.omega)
    return motion_plot(dynamics.motion, text or strings(locale), "press", flywheel, dynamics.resisting,
                       stall_angle_deg=dynamics.rest_angle_deg())


def _drawn(figure):
    """``figure`` drawn in the plots' own settings (fonts), so that its texts' extents are the SVG's."""
    with matplotlib.rc_context(settings()):
        figure.draw_without_rendering()


def _assert_legends_under_their_plots(figure) -> int:
    """Each legend's box wholly under its plot's abscissa, numbers and name, by at least the gap legend_under leaves;
    over no other plot, its title or numbers; inside the figure.  The number of legends."""
    _drawn(figure)
    page, legends = figure.bbox, 0
    for plot in figure.axes:
        legend = plot.get_legend()
        if legend is None:
            continue
        legends += 1
        box = legend.get_window_extent()
        abscissa = plot.xaxis.get_tightbbox()
        for text in [plot.xaxis.label, *plot.get_xticklabels()]:
            if text.get_text():
                assert box.y1 < text.get_window_extent().y0, text.get_text()
        gap = (abscissa.y0 - box.y1) * 72.0 / figure.dpi
        assert gap >= LEGEND_GAP - 1e-6, f"{gap:.1f} pt under the abscissa's name"
        assert page.x0 <= box.x0 and box.x1 <= page.x1 and page.y0 <= box.y0 and box.y1 <= page.y1
        for other in figure.axes:
            if other is not plot:
                # The other plot with its title, numbers and names (its own legend stands under it, in its room).
                assert not box.overlaps(other.get_tightbbox(bbox_extra_artists=[])), "on the other plot"
    return legends


@pytest.mark.parametrize("locale", LOCALES)
@pytest.mark.parametrize("case", list(CASES))
def test_each_legend_lies_under_its_plots_abscissa_clear_of_the_other_plot(case, locale):
    """The run's and the stall's legends stood at 0.13 and 0.2 of their plot's height under it: 2 pt under the name
    "t, s" of the braked run's plot, and so on the name of a shorter plot or a longer name."""
    from matplotlib import pyplot

    figure = _figure(case, locale)
    try:
        assert _assert_legends_under_their_plots(figure) == len(figure.axes)
    finally:
        pyplot.close(figure)


@pytest.mark.parametrize("locale", LOCALES)
@pytest.mark.parametrize("case", list(CASES))
def test_the_figure_with_its_legends_fits_the_height_the_note_gives_a_figure(case, locale):
    """The legends' room added, the figure is no taller than the 230 mm the HTML and Word notes give a figure on an
    A4 page, which would shrink a taller one, its words with it."""
    figure = _figure(case, locale)
    _drawn(figure)
    assert figure.get_figheight() * 25.4 <= NOTE_FIGURE_HEIGHT_MM


@pytest.mark.parametrize("locale", LOCALES)
def test_a_long_name_of_an_abscissa_in_two_lines_keeps_the_legends_under_it(locale):
    """A language whose axis names run long, set in two lines: the legends stand under the second."""
    from matplotlib import pyplot

    text = dict(strings(locale))
    for key in ("motion_time_axis", "motion_turned_axis"):
        text[key] = f"{text[key]}\n{text[key]}"
    figure = _figure("braked", locale, text)
    try:
        assert _assert_legends_under_their_plots(figure) == 2
    finally:
        pyplot.close(figure)


@pytest.mark.parametrize("case", list(CASES))
def test_the_plots_keep_the_heights_the_figure_gives_them_without_legends(case, locale="ru"):
    """The figure grows by its legends' room: laid out again at the height it was made with, its legends taken off,
    no plot is taller than it is now.  The stall's legend took its room from the plots."""
    from matplotlib import pyplot

    figure = _figure(case, locale)
    try:
        def heights() -> list[float]:
            return [axes.get_position().height * figure.get_figheight() for axes in figure.axes]

        now = heights()
        for axes in figure.axes:
            axes.get_legend().remove()
        figure.set_figheight(CASES[case])
        with matplotlib.rc_context(settings()):
            figure.tight_layout()
        # To a point: tight_layout itself lays a figure out a few tenths of a point apart from where its plots stood.
        for was, is_now in zip(heights(), now, strict=True):
            assert is_now >= was - 1.0 / 72.0
    finally:
        pyplot.close(figure)


def _glyphs(text):
    """The characters mathtext sets for a legend's text: (character, font family, size, baseline height)."""
    from matplotlib.mathtext import MathTextParser

    parsed = MathTextParser("path").parse(text.get_text(), 72, text.get_fontproperties())
    # (font, size, character, ..., y): the middle fields differ between matplotlib's versions.
    return [(chr(glyph[2]), glyph[0].family_name, float(glyph[1]), float(glyph[-1])) for glyph in parsed.glyphs]


def _assert_subscripted(text, letters) -> None:
    """Each M of ``text`` followed by its letter of ``letters`` set smaller and lower, all in DejaVu Sans."""
    glyphs = _glyphs(text)
    assert {family for _, family, _, _ in glyphs} == {"DejaVu Sans"}, text.get_text()
    found = [(glyphs[k], glyphs[k + 1]) for k in range(len(glyphs) - 1) if glyphs[k][0] == "M"]
    assert [subscript[0] for _, subscript in found] == list(letters), text.get_text()
    for (_, _, size, baseline), (_, _, sub_size, sub_baseline) in found:
        assert sub_size < 0.8 * size and sub_baseline < baseline


@pytest.mark.parametrize("locale", ["en", "ru"])
@pytest.mark.parametrize("case", ["braked", "never starts"])
def test_the_stalls_moments_have_their_letters_as_subscripts_in_dejavu_sans(case, locale, caplog):
    """Mr(φ), Md and Mr(φ) + Mt were written on one line, "Mr" as one might write "Mr Smith"; in Russian the
    subscripts are Cyrillic, which DejaVu Sans has: no glyph of mathtext's fallback or its dummy box."""
    from matplotlib import pyplot

    text = strings(locale)
    figure = _figure(case, locale)
    try:
        with warnings.catch_warnings():
            warnings.filterwarnings("error", message=".*[Gg]lyph")   # a glyph missing from the fonts
            with caplog.at_level(logging.WARNING, logger="matplotlib"):
                _drawn(figure)
        assert not [record.getMessage() for record in caplog.records if "glyph" in record.getMessage()]
        legend = figure.axes[-1].get_legend()
        labels = {item.get_text(): item for item in legend.get_texts()}
        subscripted = 0
        for key, letter in SUBSCRIPTS[locale].items():
            if text[key].format() in labels:
                _assert_subscripted(labels[text[key].format()], letter)
                subscripted += 1
        assert subscripted == 2
        braked = [item for words, item in labels.items() if words.count("$") == 4]
        assert len(braked) == (case == "braked")
        for item in braked:
            _assert_subscripted(item, BRAKED_SUBSCRIPTS[locale])
    finally:
        pyplot.close(figure)


@pytest.mark.parametrize("locale", LOCALES)
def test_the_svg_writes_the_stalls_moments_in_mathtext_but_in_chinese(locale):
    """The SVG keeps each text it draws as paths in a comment: mathtext's M with its subscript in English and
    Russian; in Chinese the plain letters, as mathtext would set the Chinese words beside them as empty boxes."""
    dynamics = _dynamics("braked", locale)
    svg = motion_figure(dynamics.motion, strings(locale), "press", None, dynamics.resisting,
                        stall_angle_deg=dynamics.rest_angle_deg())
    comments = re.findall(r"<!-- (.*?) -->", svg)
    moments = [words for words in comments if re.match(r"\$?(\\mathrm\{)?M", words) and "(φ)" in words]
    assert len(moments) == 2   # Mr alone, and Mr + Mt
    if locale == "zh":
        assert all("$" not in words for words in moments) and all(words.startswith("Mr(φ)") for words in moments)
    else:
        letter, brake = BRAKED_SUBSCRIPTS[locale]
        assert all(words.startswith(rf"$\mathrm{{M}}_\mathrm{{{letter}}}$(φ)") for words in moments)
        assert any(rf"+ $\mathrm{{M}}_\mathrm{{{brake}}}$," in words for words in moments)
        motor = SUBSCRIPTS[locale]["motion_motor_torque"]
        assert any(words.startswith(rf"$\mathrm{{M}}_\mathrm{{{motor}}}$,") for words in comments)
