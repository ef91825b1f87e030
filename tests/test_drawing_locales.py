"""The drawings in Russian and Chinese: every word from the locale files, none left in English.

Five modules draw words: the title block (render/title_block.py), the kinematic diagrams
(render/diagrams.py), the dynamics sheet (render/dynamics.py), the balancing polygons
(render/balancing.py) and the vibration figures (report/vibration_plots.py).  Each is drawn from a
real fixture or rotor in English, Russian and Chinese, and the texts of the ru and zh drawings are set
against the English one: a text they share may hold only numbers, symbols and units that every
language writes alike, and no text may hold an English word of en.toml that ru.toml and zh.toml never
use.  A Russian drawing writes its units in Russian (мм, кг, рад), as GOST 8.417 has them.  Every key
the modules look up is in each locale file itself (the English fallback of ``strings`` switched off),
and every key of their prefixes is drawn somewhere.
"""

from __future__ import annotations

import dataclasses
import functools
import html
import io
import re
import tomllib
import warnings
from importlib import resources
from pathlib import Path
from xml.etree import ElementTree

import numpy as np
import pytest
from test_kinematic_diagrams import steady_crank_as_output

import graphplan
from graphplan.analysis import analyse
from graphplan.dynamics import equivalent_model_of
from graphplan.flywheel import flywheel_for
from graphplan.kinematic_diagrams import of_analysis
from graphplan.locale import strings
from graphplan.render import balancing, diagrams, dynamics, title_block
from graphplan.render.primitives import Text
from graphplan.render.sheet import kinematics_sheet
from graphplan.report import vibration_plots
from graphplan.rotor_balancing import BalancingSpec, RotatingMass, balance
from graphplan.scene import loads

SVG = "{http://www.w3.org/2000/svg}"
KINDS = ("title_block", "diagrams", "dynamics", "balancing", "vibration")
PREFIXES = {"title_block": "tb_", "diagrams": "kd_", "dynamics": "dyn_", "balancing": "bal_", "vibration": "vib_"}
# The rotor of Rattan's "shaft of four masses" (tests/test_rotor_balancing.py), balanced in two planes,
# and one mass on a disc, balanced in its own plane.
SHAFT = [RotatingMass(18, 0.05, 0, 0.0), RotatingMass(14, 0.06, -60, 0.08), RotatingMass(16, 0.07, -135, 0.16),
         RotatingMass(12, 0.06, -270, 0.28)]
# Units as an English or Chinese drawing writes them, which a Russian one writes in Cyrillic.
LATIN_UNIT = re.compile(r"(?<![A-Za-zА-Яа-яЁёα-ωΑ-Ω])(mm|kg|rad|rpm|J|N|m/s|s/mm)(?![A-Za-zА-Яа-яЁё])")


def locale_file(locale: str) -> dict[str, str]:
    """The locale file alone, without the English that ``strings`` falls back to."""
    text = resources.files("graphplan").joinpath("locales", f"{locale}.toml").read_text(encoding="utf-8")
    return tomllib.loads(text)


@functools.cache
def english_words() -> frozenset[str]:
    """Words (two letters and more) of en.toml that neither ru.toml nor zh.toml uses, placeholders aside."""
    def words(locale: str) -> set[str]:
        texts = (re.sub(r"\{\w*\}", " ", text) for text in locale_file(locale).values())
        return {word.lower() for text in texts for word in re.findall(r"[A-Za-z]{2,}", text)}

    return frozenset(words("en") - words("ru") - words("zh"))


def english_in(text: str) -> set[str]:
    return {word for word in re.findall(r"[A-Za-z]{2,}", text) if word.lower() in english_words()}


# --- the drawings -------------------------------------------------------------------------------------------


@functools.cache
def analysis_of(name: str):
    return analyse(graphplan.load(f"fixtures/{name}.toml"))


@functools.cache
def swing_analysis():
    """The double rocker over its lever's swing, with its rocker named the output link."""
    text = Path("fixtures/double_rocker_swing.toml").read_text(encoding="utf-8")
    return analyse(loads(text.replace("count = 7", 'count = 7\nworking = { link = 4, sense = "cw" }')))


@functools.cache
def pushed_slider_analysis():
    """The slider-driven lever with its rod accelerating: the diagrams say they leave that acceleration out."""
    text = Path("fixtures/slider_driven.toml").read_text(encoding="utf-8")
    return analyse(loads(text.replace("acceleration = 0.0 ", "acceleration = 0.5 ")))


@functools.cache
def models():
    """A crank's equivalent model with its flywheel moved to a faster shaft, and a slider driver's model."""
    crank = equivalent_model_of(analysis_of("ratchet_crank_rocker"))
    slider = equivalent_model_of(analysis_of("slider_driven"))
    return crank, flywheel_for(crank, 0.02, shaft_rpm=1500.0), slider


def svg_texts(svg: str) -> list[str]:
    return ["".join(element.itertext()) for element in ElementTree.fromstring(svg).iter(f"{SVG}text")]


def figure_texts(svg: str) -> list[str]:
    """The texts of a matplotlib SVG: drawn as paths, each written out in the comment before it."""
    found = [html.unescape(text) for text in re.findall(r"<!-- (.*?) -->", svg)]
    # Log-scale ticks are mathtext (10^{-1}): the same in every language.
    return [re.sub(r"^\$\\mathdefault\{(.*)\}\$$", r"\1", text) for text in found]


def title_block_texts(words) -> list[str]:
    """The three standard forms in ``words`` (labels of a locale), filled with what is the same in any language."""
    found = []
    for form in ("eskd", "gb", "iso"):
        fields = title_block.TitleBlockFields(title="", drawing=words["sheet_kinematics"], scale="1:2", sheet=1,
                                              sheets=2, designation="ТММ.01.00", date="2024-05-20")
        found += [item.text for item in title_block.title_block(form, fields, words, (0.0, 0.0))
                  if isinstance(item, Text)]
    return found


def drawn(kind: str, text=None, labels=None) -> list[str]:
    """The texts of every variant of the drawing ``kind`` in ``text`` (a locale's strings; None: the default)."""
    if kind == "title_block":
        return title_block_texts(labels)
    if kind == "diagrams":
        # A rocker (ψ, ω, ε; working and idle strokes), a slider (s, v, a), a lever over a slider driver's
        # travel (t), a rocker over its lever's swing (Δφ) and a steady crank (an ε nought throughout).
        runs = [analysis_of(name) for name in ("ratchet_crank_rocker", "engine_slider_crank", "slider_driven")]
        records = [of_analysis(analysis) for analysis in (*runs, swing_analysis(), pushed_slider_analysis())]
        return [t for record in (*records, steady_crank_as_output()[1])
                for t in svg_texts(diagrams.diagrams_svg(record, text))]
    if kind == "dynamics":
        crank, flywheel, slider = models()
        # A machine that keeps within δ unaided is drawn from a flywheel record with no inertia to add.
        unaided = dataclasses.replace(flywheel, inertia=-1.0)
        # A Je the same all the cycle (a flywheel from load diagrams alone): one flywheel, no energy–mass diagram.
        steady = dataclasses.replace(crank, inertia=np.full(len(crank.inertia), crank.mean_inertia))
        # One whose own Je the scene takes as zero (the flywheel starter's press): its JF has no Je subtracted.
        unowned = dataclasses.replace(crank, inertia=np.zeros(len(crank.inertia)))
        # A resisting moment (force) the same all the run, its value written beside its line.
        crank_resists_level = dataclasses.replace(crank, resisting=np.full(len(crank.resisting), -100.0))
        slider_resists_level = dataclasses.replace(slider, resisting=np.full(len(slider.resisting), -100.0))
        return [t for model, wheel in ((crank, flywheel), (crank, unaided), (steady, flywheel), (unowned, flywheel),
                                       (slider, None), (crank_resists_level, None), (slider_resists_level, None))
                for t in svg_texts(dynamics.dynamics_svg(model, wheel, text))]
    if kind == "balancing":
        two_planes = balance(BalancingSpec(SHAFT, planes=(0.04, 0.22), correction_radius=0.05))
        disc = balance(BalancingSpec([RotatingMass(1, 0.1, 30)], correction_radius=0.1))
        # A mass 0.02 m from plane R, whose share in plane L is too short to draw and is told under its polygon.
        near_plane = balance(BalancingSpec([*SHAFT[:2], RotatingMass(1, 0.03, 90, 0.20)], planes=(0.04, 0.22),
                                           correction_radius=0.05))
        # One plane for masses in several: the couple it leaves told under its polygon.
        one_plane = balance(BalancingSpec(SHAFT, planes=(0.04,), correction_radius=0.05))
        return [t for result in (two_planes, disc, near_plane, one_plane)
                for t in svg_texts(balancing.balancing_svg(result, text))]
    from graphplan.vibration import Shaft, VibrationSpec

    found = []
    # A machine with an unbalance and isolating mounts designed, an instrument on a moving base, and a disc on a
    # shaft whose whole support is designed.
    rotating = VibrationSpec(mass=100.0, unbalance=0.02, stiffness=1e5, damping_ratio=0.1, omega=60.0)
    shaken = VibrationSpec(mass=20.0, unbalance=0.0, stiffness=2e4, damping_ratio=0.1, omega=60.0, base_amplitude=1e-3)
    disc = Shaft(modulus=2.1e11, second_moment=4e-8, length=0.8)
    whirling = VibrationSpec(mass=20.0, unbalance=0.001, stiffness=disc.stiffness, damping_ratio=0.1, omega=400.0,
                             shaft=disc)
    for spec in (rotating, shaken, whirling):
        words = vibration_plots.words_for(spec, text)
        stream = io.StringIO()
        vibration_plots.magnification_figure(stream, operating=(1.3, 0.1), text=words)
        found += figure_texts(stream.getvalue())
        stream = io.StringIO()
        vibration_plots.transmissibility_figure(stream, operating=(1.3, 0.1), design=(2.5, 0.2), text=words)
        found += figure_texts(stream.getvalue())
    stream = io.StringIO()  # next to no damping at resonance: the working point above the ordinate
    vibration_plots.magnification_figure(stream, operating=(0.999, 1e-9), text=text)
    return found + figure_texts(stream.getvalue())


@functools.cache
def texts_of(kind: str, locale: str) -> frozenset[str]:
    return frozenset(drawn(kind, strings(locale), title_block.labels(locale)))


# --- no English in a Russian or Chinese drawing -------------------------------------------------------------


def test_the_english_words_are_found_in_an_english_drawing():
    """The check below can fail: the English drawings are full of the words it looks for."""
    assert {"plane", "diagram", "scale", "flywheel", "transmissibility", "rpm", "at"} <= english_words()
    for kind in KINDS:
        assert set().union(*(english_in(text) for text in texts_of(kind, "en"))), kind


@pytest.mark.parametrize("locale", ["ru", "zh"])
@pytest.mark.parametrize("kind", KINDS)
def test_a_russian_or_chinese_drawing_shares_with_english_only_numbers_symbols_and_units(kind, locale):
    english, other = texts_of(kind, "en"), texts_of(kind, locale)
    worded = {text for text in english if english_in(text)}
    assert worded and not worded & other
    shared = english & other
    assert not {text for text in shared if english_in(text)}
    assert not {text: english_in(text) for text in other if english_in(text)}


@pytest.mark.parametrize("kind", KINDS)
def test_a_russian_drawing_writes_its_units_in_russian(kind):
    if kind in ("diagrams", "dynamics", "balancing"):  # the others are dimensionless
        assert any(LATIN_UNIT.search(text) for text in texts_of(kind, "en"))
    assert not {text for text in texts_of(kind, "ru") if LATIN_UNIT.search(text)}


def test_chinese_drawings_are_in_chinese():
    for kind in KINDS:
        chinese = [text for text in texts_of(kind, "zh") if re.search(r"[\u4e00-\u9fff]", text)]
        assert len(chinese) >= 2, kind


# --- the locale files ---------------------------------------------------------------------------------------


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_every_key_the_drawings_look_up_is_in_the_locale_file_itself(monkeypatch, locale):
    own = locale_file(locale)
    for module in (title_block, diagrams, dynamics, balancing):
        monkeypatch.setattr(module, "strings", lambda _locale: own)
    monkeypatch.setattr(vibration_plots, "locale_strings", lambda _locale: own)
    # The modules' default words are now this file alone: a key it lacks is a KeyError.
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)  # a missing CJK font is not what this test is about
        for kind in KINDS:
            assert drawn(kind, None, title_block.labels("en"))


def test_every_key_of_the_drawings_prefixes_is_drawn():
    english = strings("en")
    # Named by render/sheet.py for the block's drawing name, not by a form; a position's word and its shorter one
    # are what title_block.fitting_name shortens such a name by.
    by_the_sheets = {"tb_sheet_forces", "tb_sheet_forces_position", "tb_sheet_forces_friction_position",
                     "tb_sheet_with_load_diagrams", "tb_sheet_dynamics", "tb_sheet_balancing",
                     "tb_position_word", "tb_position_short"}
    for kind, prefix in PREFIXES.items():
        keys = {key for key in english if key.startswith(prefix)}
        marked = {key: f"[[{key}]]{value}" for key, value in english.items() if key.startswith(prefix)}
        labels = {key.removeprefix("tb_"): value for key, value in marked.items()}
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", UserWarning)
            shown = {key for text in drawn(kind, marked, labels) for key in re.findall(r"\[\[(\w+)\]\]", text)}
        expected = keys - by_the_sheets if kind == "title_block" else keys
        assert shown == expected, (kind, expected - shown, shown - expected)


def test_labels_serve_every_locale_file_and_refuse_another():
    assert title_block.locales() == ("en", "ru", "zh")
    assert title_block.labels("ru")["eskd_designed"] == "Разраб."
    assert title_block.labels("zh")["gb_stage"] == "阶段标记"
    with pytest.raises(ValueError, match=r"no title block strings for locale 'de'; known: en, ru, zh"):
        title_block.labels("de")


# --- a Russian sheet ----------------------------------------------------------------------------------------


def test_a_russian_sheet_has_the_eskd_block_in_russian():
    """The kinematic diagrams of the ratchet on an A1 sheet of a Russian scene: GOST 2.104's words."""
    analysis = analysis_of("ratchet_crank_rocker")
    panel = diagrams.layout(of_analysis(analysis), strings("ru"))
    (sheet,) = kinematics_sheet([panel], "A1", locale="ru", title="Храповой механизм")
    block = [item.text for layer in sheet.layers if layer.name == "title-block" for item in layer.items
             if isinstance(item, Text)]
    for word in ("Изм.", "Лист", "№ докум.", "Подп.", "Дата", "Разраб.", "Пров.", "Т.контр.", "Н.контр.", "Утв.",
                 "Лит.", "Масса", "Масштаб", "Листов", "Кинематический анализ"):
        assert word in block, word
    # The name is lettered at the block's largest height in as many lines as that takes.
    assert "Храповой механизм" in " ".join(block)
    everything = svg_texts(sheet.svg())
    assert "Кинематические диаграммы выходного звена 4" in everything
    assert not {text for text in everything if english_in(text) or LATIN_UNIT.search(text)}


def test_a_chinese_figure_finds_its_cjk_font():
    """matplotlib draws a missing glyph as a box and says so; with Noto Sans CJK installed it must not."""
    from matplotlib import font_manager

    if not any("NotoSansCJK" in path for path in font_manager.findSystemFonts()):
        pytest.skip("Noto Sans CJK is not installed")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        vibration_plots.magnification_figure(io.StringIO(), operating=(1.3, 0.1), text=strings("zh"))
    assert not [str(w.message) for w in caught if "missing from font" in str(w.message)]


def test_a_chinese_force_sheet_sets_its_scales_off_with_the_full_width_comma():
    """«μl = 0.004 m/mm, 力：μF = 100 N/mm，最短 10 mm» mixed a Latin comma with Chinese ones and left «最短» unclear (a
    Chinese student's reading): the scales are set off by 「，」, the least arrow said to be the arrows'.  «（不短于 10 mm）»
    then said neither what is not shorter nor that shorter arrows are drawn longer, so a 10 mm Fu5 read as 1000 N at
    μF = 100 N/mm: the caption says arrows shorter than 10 mm are drawn at 10 mm, as the Russian one does."""
    from graphplan.render import forces as force_layout
    from graphplan.render.drawings import force_sheet, with_length_scale

    analysis = with_length_scale(analyse(dataclasses.replace(graphplan.load("fixtures/shaper_six_bar.toml"),
                                                             locale="zh")))
    layers = force_layout.layout(force_sheet(analysis, analysis.plans[0]))
    # A caption's lines joined as they read, a line broken after 「，」 or before 「（」 with nothing lost.
    captions = "".join(item.text for layer in layers if layer.name.endswith("-caption")
                       for item in layer.items if isinstance(item, Text))
    assert "μl = 0.0025 m/mm，力箭头的比例尺 μF = 100 N/mm（短于 10 mm 的箭头画成 10 mm）" in captions
    assert "m/mm, " not in captions and "最短" not in captions


def test_a_chinese_caption_separates_its_clauses_full_width_where_it_has_chinese_words_else_latin():
    """The rule of the Chinese drawings (as the balancing polygons' lines have it): a caption line with Chinese words
    in it separates its clauses with ，and ；, a line of symbols and numbers alone with , and ; (a full-width one
    after Latin alone read as a slip).  The shaper's sheets mixed them: «滑动摩擦：fE = 0.1, φ = arctan f = …,»,
    «μF = 40 N/mm; μs = 0.0025 m/mm，行程 H = …», «L = 240 mm；  μt = …» (a hunt's sheet 4 and diagrams)."""
    from graphplan.load_diagrams import of_analysis as load_diagrams_of
    from graphplan.render import forces as force_layout
    from graphplan.render import load_diagrams
    from graphplan.render.drawings import force_sheet
    from graphplan.starters import starter

    chinese = re.compile(r"[\u4e00-\u9fff]")

    def follows_the_rule(line: str) -> bool:
        return not re.search(r"[,;] ", line) if chinese.search(line) else not re.search(r"[，；]", line)

    from graphplan.render.drawings import POSITIONS_FIELD_MM, paths_extent
    from graphplan.scales import fit_scale

    scene = graphplan.load_text(starter("shaper", "zh"))
    # The captions' commas and semicolons are the same at any μl: fixed at the one that draws the paths into the plan
    # of positions' field, not chosen by laying every sheet out at a few μl (eight seconds of this test).
    length_scale = fit_scale(paths_extent(analyse(scene)), POSITIONS_FIELD_MM)
    fixed = dataclasses.replace(scene.drawing, length_scale=length_scale)
    analysis = analyse(dataclasses.replace(scene, drawing=fixed))
    words = strings("zh")
    captions = [line for position in analysis.plans for friction in (False, True)
                for row in force_layout.rows(force_sheet(analysis, position, friction)).drawings
                for drawing in row for line in drawing.caption]
    assert any(line.startswith("滑动摩擦：") for line in captions)
    assert [line for line in captions if not follows_the_rule(line)] == []
    # The diagrams' scale lines are broken to their width: read whole, each as its words make it.
    for layers in (load_diagrams.layout(load_diagrams_of(analysis), words), diagrams.layout(of_analysis(analysis), words)):
        lines = [item.text for layer in layers for item in layer.items if isinstance(item, Text)]
        scales = "".join(line for line in lines if "μ" in line or "行程" in line)
        assert "μ" in scales
        assert not re.search(r"[,;] μ", scales) and not re.search(r"m；\s*μt", scales), scales
    loads_scale = " ".join(item.text for layer in load_diagrams.layout(load_diagrams_of(analysis), words)
                           for item in layer.items if isinstance(item, Text))
    assert "N/mm；" in loads_scale


def test_chinese_names_the_velocity_and_acceleration_plans_as_the_plan_sheets_do():
    """The plan sheets say 速度多边形 and 加速度多边形; the grid of every position's plans, the velocity diagram's
    legend and the curve of Je read off the plans said 速度图, another term for the same drawing (a hunt's zh sheets)."""
    words = strings("zh")
    assert (words["velocity_plan_title"], words["acceleration_plan_title"]) == ("速度多边形", "加速度多边形")
    assert [key for key, value in words.items() if "速度图" in value] == []
    for key in ("velocity_plans_heading", "kd_plans", "dyn_inertia_plans", "velocity_plan_errors"):
        assert words["velocity_plan_title"] in words[key], key
