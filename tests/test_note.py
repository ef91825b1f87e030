"""The explanatory note (note.md, note.html) and the localised errors.md and forces.md.

The note's numbers are checked against the analytic solution (``analysis.motion``, ``statics``), not
against the plan records it prints from; its arithmetic is checked by redoing it from the numbers it
prints; its language by the words it must not contain; its HTML by parsing it.
"""

from __future__ import annotations

import dataclasses
import math
import re
import tomllib
from functools import cache
from html.parser import HTMLParser
from importlib import resources
from pathlib import Path
from string import Formatter

import numpy as np
import pytest
from light_runs import on_no_sheet
from sheet_texts import flat

import graphplan
from graphplan.analysis import analyse
from graphplan.locale import strings
from graphplan.report import forces as force_report
from graphplan.report import tables
from graphplan.report.html import symbols_html, to_html
from graphplan.report.note import note_html, note_markdown
from graphplan.run import as_asked

FIXTURES = Path(__file__).resolve().parent.parent / "fixtures"
# One fixture of every group kind and driver: RRR, RPR + RRP (Coriolis), RPP (translating yoke),
# RPR + PRP, a slider driver, RRP on a frame guide.
KINDS = ("ratchet_crank_rocker", "shaper_six_bar", "scotch_yoke", "tangent_mechanism_prp", "slider_driven",
         "engine_slider_crank")
TITLES = {"ru": "Кривошипно-коромысловый механизм", "zh": "曲柄摇杆机构", "en": "Crank-rocker mechanism"}
LOCALES = ("en", "ru", "zh")


@cache
def analysis_of(name: str, locale: str):
    scene = graphplan.load(FIXTURES / f"{name}.toml")
    # The title is the user's own text, in whatever language the user wrote it.
    return analyse(dataclasses.replace(scene, locale=locale, title=TITLES[locale]))


@cache
def note_of(name: str, locale: str) -> str:
    return note_markdown(analysis_of(name, locale))


def unsheeted_note(name: str, locale: str) -> str:
    """The note of the fixture ``name`` in ``locale``, drawn on no sheet: a note whose scene gives no μl lays the
    course sheets out at a few μl to choose it, seconds of work, where the μl fitted to the plan of positions' field
    is the same.  For the fixtures read so (triad_class_iii in ru, triad_with_slider in en, double_rocker_swing in zh)
    the note came out byte-identical to the note on the scene's own sheet."""
    scene = dataclasses.replace(graphplan.load(FIXTURES / f"{name}.toml"), locale=locale)
    return note_markdown(analyse(as_asked(scene, sheet="none")))


def locale_file(locale: str) -> dict[str, str]:
    text = resources.files("graphplan").joinpath("locales", f"{locale}.toml").read_text(encoding="utf-8")
    return tomllib.loads(text)


def number(text: str) -> float:
    """A number as the note prints it: true minus sign, the locale's decimal mark."""
    return float(text.replace("−", "-").replace(",", "."))


def agrees(printed: str, exact: float, digits: int = 5) -> bool:
    """Whether ``printed`` is ``exact`` to the precision it is printed with (``digits`` significant digits)."""
    value = number(printed)
    if exact == 0:
        return value == 0
    unit = 10.0 ** (math.floor(math.log10(abs(exact))) - digits + 1)
    return abs(value - exact) <= 0.5 * unit * (1 + 1e-9) + 1e-12 * abs(exact)


def table_after(note: str, caption: str) -> list[list[str]]:
    """The rows (cells) of the Markdown table that follows the line starting with ``caption``."""
    lines = note.splitlines()
    start = next(i for i, line in enumerate(lines) if line.startswith(caption))
    rows, i = [], start + 1
    while not lines[i].startswith("|"):
        i += 1
    while i < len(lines) and lines[i].startswith("|"):
        rows.append([cell.strip() for cell in lines[i].strip("|").split("|")])
        i += 1
    return rows[2:]  # without the header and the alignment row


# The locale files.

def test_every_locale_has_exactly_the_keys_and_placeholders_of_english():
    english = locale_file("en")
    fields = Formatter()

    def root(name: str) -> str:  # what the code passes: {date.year} is of the value date
        return re.split(r"[.\[]", name)[0]

    for locale in ("ru", "zh"):
        other = locale_file(locale)
        assert set(other) == set(english), locale
        for key, text in english.items():
            wanted = {root(name) for _, name, _, _ in fields.parse(text) if name}
            found = {root(name) for _, name, _, _ in fields.parse(other[key]) if name}
            assert found == wanted, (locale, key)


def english_words() -> set[str]:
    """The English words (four letters and more) of en.toml that no other locale file also uses."""
    def words_of(locale: str) -> set[str]:
        texts = (re.sub(r"\{\w*\}", " ", text) for text in locale_file(locale).values())  # not the placeholders
        return {word.lower() for text in texts for word in re.findall(r"[A-Za-z]{4,}", text)}

    return words_of("en") - words_of("ru") - words_of("zh")


@pytest.mark.parametrize("locale", ["ru", "zh"])
@pytest.mark.parametrize("name", KINDS)
def test_a_note_in_russian_or_chinese_has_no_english_word(name, locale):
    english = english_words()
    assert {"velocity", "plan", "position", "group", "link"} <= english  # the check can fail
    found = {w for w in re.findall(r"[A-Za-z]{4,}", note_of(name, locale)) if w.lower() in english}
    assert not found, found
    for report in (tables.markdown(analysis_of(name, locale)), force_report.markdown(analysis_of(name, locale))):
        found = {w for w in re.findall(r"[A-Za-z]{4,}", report) if w.lower() in english}
        assert not found, found


@pytest.mark.parametrize("name", KINDS)
def test_every_heading_of_a_chinese_note_is_in_chinese(name):
    headings = [line for line in note_of(name, "zh").splitlines() if line.startswith("#")]
    assert len(headings) >= 8
    for heading in headings:
        assert re.search(r"[\u4e00-\u9fff]", heading), heading


@pytest.mark.parametrize("name", [*KINDS, "double_rocker_swing"])
def test_a_chinese_note_ends_its_sentences_and_lists_its_positions_the_chinese_way(name):
    """「pa = VA/μV = 1/0.01 = 100.00 mm.」, 「**计入运动副摩擦.**」 and 「位置 3, 10」 were set with the Latin full stop and
    comma (a Chinese student's reading): a sentence ends in 。, a list of positions takes 、, formulas in a line ；."""
    if name in KINDS:
        note = note_of(name, "zh")
    else:
        note = unsheeted_note(name, "zh")
    prose = [line for line in note.splitlines() if line and not line.startswith(("|", "!", "#"))]
    assert not [line for line in prose if re.search(r"[.;]\**$", line)]
    # Nor a Latin semicolon between two formulas («R34 + ΣF4 + R14 = 0;  R43 + …», «Fb = … N; |Mb| = …»).
    assert not [line for line in prose if ";" in line]
    # No Latin space beside full-width punctuation («比较。 运动副反力», «N （负号»).
    assert not [line for line in prose if re.search(r"[。，；：！？、）] | （", line)]
    listed = re.search(r"对位置 ([\d、]+) ", note) or re.search(r"位置 ([\d、, ]+)", note)
    assert listed and "," not in listed[1]


def test_the_russian_note_writes_as_the_russian_textbooks_do():
    note = note_of("ratchet_crank_rocker", "ru")
    assert "W = 3n − 2p5 − p4 = 3·3 − 2·4 − 0 = 1" in note  # Chebyshev's formula with the numbers
    assert "| II(3,4) | класс II, порядок 2 | 3, 4 | A, B, C | ВВВ (RRR) |" in note
    assert "VA = ω2·lOA = 17·0,175 = 2,975 м/с" in note  # decimal comma, Russian units
    assert "μa = aA/πa = 50,575/100 = 0,50575 (м/с²)/мм" in note  # the acceleration pole is π
    assert "Формула строения механизма: I(1,2) → II2(3,4)" in note
    chinese = note_of("ratchet_crank_rocker", "zh")
    assert "F = 3n − 2PL − PH = 3×3 − 2×4 − 0 = 1" in chinese  # 机械原理's own notation


@pytest.mark.parametrize("locale", LOCALES)
def test_sections_are_numbered_in_order_with_no_point_after_the_number_in_russian_and_chinese(locale):
    """GOST 2.105 and GB/T 7713 write «3.1 Положение 5», «3.1 位置 5»; English writes "3.1. Position 5"."""
    note = note_of("shaper_six_bar", locale)
    numbered = re.findall(r"^#{2,3} (\d+(?:\.\d+)?)(\.?) \S", note, flags=re.MULTILINE)
    assert len(numbered) >= 6
    assert {point for _, point in numbered} == ({"."} if locale == "en" else {""})
    sections = [int(number) for number, _ in numbered if "." not in number]
    assert sections == list(range(1, len(sections) + 1))
    for section in sections:
        subsections = [int(number.split(".")[1]) for number, _ in numbered if number.startswith(f"{section}.")]
        assert subsections == list(range(1, len(subsections) + 1))


# The numbers.

def value_at(values, index: int) -> float:
    """An analytic scalar at a position (a constant is the same at every one)."""
    return float(np.atleast_1d(values)[index if np.ndim(values) else 0])


def velocity(analysis, point: str, index: int) -> complex:
    return complex(*analysis.motion.point(point).v[index])


def motion_value(analysis, index: int, quantity: str) -> float | None:
    """A quantity of the velocity table straight from the analytic solution, or None for a sliding one."""
    motion = analysis.motion
    if quantity.startswith("ω"):
        return value_at(motion.link(int(quantity[1:])).omega, index)
    body = quantity[1:]
    if body in motion.points:
        return abs(velocity(analysis, body, index))
    names = sorted(motion.points, key=len, reverse=True)
    for first in names:
        rest = body[len(first):]
        if body.startswith(first) and rest in motion.points:
            return abs(velocity(analysis, first, index) - velocity(analysis, rest, index))
    return None


@pytest.mark.parametrize("locale", LOCALES)
@pytest.mark.parametrize("name", KINDS)
def test_the_velocity_table_is_the_analytic_solution_to_the_printed_digits(name, locale):
    analysis = analysis_of(name, locale)
    note = note_of(name, locale)
    caption = {"en": "Table", "ru": "Таблица", "zh": "表"}[locale]
    checked = 0
    for plan in analysis.plans:
        title = {"en": f"Velocities, position {plan.number}", "ru": f"Скорости, положение {plan.number}",
                 "zh": f"速度，位置 {plan.number}"}[locale]
        line = next(line for line in note.splitlines() if line.startswith(caption) and line.endswith(title))
        for quantity, _segment, _mm, by_plan, exact, _unit in table_after(note, line):
            value = motion_value(analysis, plan.index, quantity)
            if value is None:
                continue
            assert agrees(exact, value), (quantity, exact, value)
            assert agrees(by_plan, value), (quantity, by_plan, value)  # the construction is exact
            checked += 1
    assert checked >= 10


@pytest.mark.parametrize("name", KINDS)
def test_the_scale_arithmetic_reproduces_the_scales_of_the_plans(name):
    analysis = analysis_of(name, "en")
    note = note_of(name, "en")
    pole = r"μ(V|a) = (?:VA|aA)/pa = ([\d.]+)/([\d.]+) = ([\d.]+)"
    standard = (r"μ(V|a) ≥ ([\d.e−]+)/150 = [\d.e−]+, and the next larger standard scale factor is taken: "
                r"μ[Va] = ([\d.e−]+)")
    matches = sorted([*re.finditer(pole, note), *re.finditer(standard, note)], key=lambda match: match.start())
    scales = [scale for plan in analysis.plans for scale in (plan.velocity.scale, plan.acceleration.scale)]
    assert len(matches) == len(scales)
    assert [match[1] for match in matches] == ["V", "a"] * len(analysis.plans)
    for match, scale in zip(matches, scales):
        if match.re.pattern == pole:  # μ = (driver's value)/(its segment)
            _, value, segment, printed = match.groups()
            assert number(value) / number(segment) == pytest.approx(scale, rel=1e-4)
        else:  # the smallest standard scale that fits the plan into its field
            _, least, printed = match.groups()
            assert number(printed) >= number(least) / 150 * (1 - 1e-9)
        assert agrees(printed, scale)
    # The worked example's own scales (shared/fixtures-data.md, "Drawing choices of the example"):
    # pa = 150 mm gives μV = 0.01983 (m/s)/mm, pa = 100 mm gives μa = 0.50575 (m/s²)/mm.
    ratchet = note_of("ratchet_crank_rocker", "en")
    assert "μV = VA/pa = 2.975/150 = 0.019833 (m/s)/mm" in ratchet
    assert "μa = aA/pa = 50.575/100 = 0.50575 (m/s²)/mm" in ratchet


def test_the_driver_velocity_and_the_similarity_proportions_hold_against_the_motion():
    analysis = analysis_of("ratchet_crank_rocker", "en")
    note = note_of("ratchet_crank_rocker", "en")
    omega, length, speed = re.search(r"VA = ω2·lOA = ([\d.]+)·([\d.]+) = ([\d.]+) m/s", note).groups()
    assert number(omega) * number(length) == pytest.approx(number(speed), rel=1e-12)
    assert agrees(speed, abs(velocity(analysis, "A", 0)))
    # as3 = ab·lAS3/lAB on the velocity plan of position 5: as3·μV is |vS3 − vA| of the analytic solution.
    plan = next(p for p in analysis.plans if p.number == 5)
    section = note[note.index("### 3.1."):note.index("#### Acceleration plan")]
    proportions = re.findall(r"- (\w+): (\w+) = (\w+)·l(\w+)/l(\w+) = ([\d.]+)·([\d.]+)/([\d.]+) = ([\d.]+) mm",
                             section)
    assert {p[0] for p in proportions} >= {"s2", "s3", "e", "s4"}
    spec = {s.name: s for s in analysis.scene.points}
    for letter, segment, base, along, span, base_mm, part, whole, result in proportions:
        point = letter.upper()
        assert number(base_mm) * number(part) / number(whole) == pytest.approx(number(result), abs=0.006)
        start = {"a": "A", "b": "B", "p": spec[point].start}[segment[0]]
        relative = abs(velocity(analysis, point, plan.index) - velocity(analysis, start, plan.index))
        assert number(result) * plan.velocity.scale == pytest.approx(relative, abs=0.006 * plan.velocity.scale)
        if spec[point].offset == 0:
            assert number(part) == pytest.approx(spec[point].at, rel=1e-4)  # lAS3 is the scene's own
    # The off-line point E gets the second side of its triangle.
    assert "be = ab·lBE/lAB" in section and "the triangle abe is similar to the triangle ABE" in section


def test_the_coriolis_component_is_twice_omega_times_the_sliding_velocity():
    analysis = analysis_of("shaper_six_bar", "en")
    note = note_of("shaper_six_bar", "en")
    found = re.findall(r"\| aA4A3ᵏ \| 2·ω(\d)·VA4A3 \(ω3 = ω4\) = 2·([\d.]+)·([\d.]+) = ([\d.]+) m/s² \|", note)
    # The block's ω3 is named as the slotted link's ω4, which the note works out; its own it does not.
    assert len(found) == len(analysis.plans) and "- ω4 = " in note and "- ω3 = " not in note
    for (link, omega, sliding, value), plan in zip(found, analysis.plans):
        i = plan.index
        slide = next(s for s in analysis.motion.slides if s.joint == "A")
        exact = 2 * abs(value_at(analysis.motion.link(4).omega, i)) * abs(value_at(slide.velocity, i))
        assert agrees(omega, abs(value_at(analysis.motion.link(int(link)).omega, i)))
        assert agrees(sliding, abs(value_at(slide.velocity, i)))
        assert agrees(value, exact)


def test_the_balancing_moment_by_the_lever_is_the_linear_systems():
    analysis = analysis_of("ratchet_crank_rocker", "en")
    note = note_of("ratchet_crank_rocker", "en")
    # Fb as the lever drawing names it; the product of the magnitudes is |Mb|, its sense after it.
    found = re.findall(r"Fb = \|Σ\(F·h\)\|/pa = ([\d.]+)/([\d.]+) = ([\d.]+) N; \|Mb\| = Fb·lOA = ([\d.]+)·([\d.]+) = "
                       r"([\d.]+) N·m, (counter-clockwise|clockwise)", note)
    assert len(found) == 2
    for (total, pa, force, force_again, arm, moment, sense), plan in zip(found, analysis.plans):
        exact = float(analysis.equilibrium.balancing[plan.index])
        assert number(total) / number(pa) == pytest.approx(number(force), rel=1e-4)
        assert force == force_again and number(arm) == 0.175
        assert number(force) * number(arm) == pytest.approx(abs(exact), rel=1e-4)
        assert agrees(moment, abs(exact), 6) and (sense == "clockwise") == (exact < 0)
    # Each moment equation solves to what it prints.
    for total, arm, value in re.findall(r"⇒ R\d+τ = −?\(?(−?[\d.]+)\)?/([\d.]+) = (−?[\d.]+) N", note):
        assert abs(number(total) / number(arm)) == pytest.approx(abs(number(value)), rel=1e-3)


def test_the_note_and_forces_md_print_the_same_tables():
    analysis = analysis_of("ratchet_crank_rocker", "en")
    note, forces_md, errors_md = note_of("ratchet_crank_rocker", "en"), force_report.markdown(analysis), \
        tables.markdown(analysis)
    rows = [line for line in forces_md.splitlines() if line.startswith("| ") and "---" not in line]
    rows += [line for line in errors_md.splitlines() if line.startswith("| ") and "---" not in line]
    assert len(rows) > 80
    for row in rows:
        assert row in note, row


@pytest.mark.parametrize("name", KINDS)
def test_each_moment_equation_of_forces_md_gives_its_unknown_in_its_unit(name):
    """«R45τ = 14.196», «Mb = −258.06» had no unit beside terms in N·m (a Chinese student's reading): a force
    found from the moments is in N, a moment (Mb, a shift times its force R14·x) in N·m."""
    analysis = analysis_of(name, "en")
    if analysis.equilibrium is None:
        pytest.skip("no forces")
    found = re.findall(r"ΣM\w+\([\d,]+\) = 0 → (\S+) = ([−\d.e]+) (\S+?)(?:;|$)", force_report.markdown(analysis),
                       flags=re.MULTILINE)
    assert found
    for unknown, _, unit in found:
        assert unit == ("N·m" if unknown.startswith("M") or unknown.endswith("·x") else "N"), (unknown, unit)
    assert all(line.endswith(" N") or " N; " in line
               for line in force_report.markdown(analysis).splitlines() if "ΣFτ(" in line)


def test_friction_reaches_the_note_and_forces_md():
    from graphplan.scene import FrictionSpec

    scene = graphplan.load(FIXTURES / "ratchet_crank_rocker.toml")
    pairs = tuple(FrictionSpec(f"friction[{k}]", joint, None, 0.12, 0.02, None) for k, joint in enumerate("OABC"))
    analysis = analyse(dataclasses.replace(scene, friction=pairs))
    note, forces_md = note_markdown(analysis), force_report.markdown(analysis)
    for plan in analysis.plans:
        balancing = plan.with_friction.balancing
        exact = float(analysis.with_friction.balancing[plan.index])
        # The fixture is Russian: its balancing moment is the textbook's Mу (уравновешивающий).
        assert f"Mу = {force_report.number(balancing, 6, ',')} Н·м" in note
        assert f"Mу = {force_report.number(balancing, 6, ',')} Н·м" in forces_md
        assert agrees(force_report.number(balancing, 6), exact, 6)
    assert "| Mу с трением, Н·м | η |" in forces_md
    # η is the smaller ratio: Mb0/Mb where the crank drives the load, Mb/Mb0 where the load drives the crank back.
    omega = analysis.mechanism.driver.omega
    for plan in analysis.plans:
        ideal, rubbing = plan.forces.balancing, plan.with_friction.balancing
        ratio, eta = ("Mу0/Mу", ideal / rubbing) if ideal * omega > 0 else ("Mу/Mу0", rubbing / ideal)
        assert f"КПД η = {ratio} = {force_report.number(eta, 4, ',')}" in note


# The localised reports.

def test_errors_md_and_forces_md_keep_their_numbers_in_every_language():
    def numbers(text: str) -> list[str]:
        # The decimal mark is the language's (a comma in Russian); a group's label, II(3,4), has its comma in all.
        return [n.replace(",", ".") for n in re.findall(r"−?-?\d+(?:[.,]\d+)?(?:e[−-]\d+)?", text)]

    for name in ("ratchet_crank_rocker", "shaper_six_bar"):
        reports = {locale: (tables.markdown(analysis_of(name, locale)), force_report.markdown(analysis_of(name, locale)))
                   for locale in LOCALES}
        for kind in range(2):
            english = numbers(reports["en"][kind])
            for locale in ("ru", "zh"):
                assert numbers(reports[locale][kind]) == english, (name, locale, kind)
    russian = force_report.markdown(analysis_of("ratchet_crank_rocker", "ru"))
    assert "| рычаг Жуковского | 49,0173 |" in russian and "## Положение 5" in russian
    assert "| ω4 | рад/с | 2,1554 |" in tables.markdown(analysis_of("ratchet_crank_rocker", "ru"))


# The HTML page.

VOID = {"meta", "br", "hr", "img", "input", "link"}


class TagBalance(HTMLParser):
    def __init__(self) -> None:
        super().__init__()
        self.open: list[str] = []
        self.errors: list[str] = []
        self.seen: dict[str, int] = {}

    def handle_starttag(self, tag, attrs):
        self.seen[tag] = self.seen.get(tag, 0) + 1
        if tag not in VOID:
            self.open.append(tag)

    def handle_startendtag(self, tag, attrs):
        # A void element self-closed (markdown-it's <br />, <img … />) opens and closes nothing.
        self.handle_starttag(tag, attrs)
        if tag not in VOID:
            self.handle_endtag(tag)

    def handle_endtag(self, tag):
        if not self.open or self.open[-1] != tag:
            self.errors.append(f"</{tag}> closes {self.open[-1:] or 'nothing'}")
        else:
            self.open.pop()


@pytest.mark.parametrize("locale", LOCALES)
def test_the_html_note_is_well_formed_and_carries_every_table(locale):
    analysis = analysis_of("shaper_six_bar", locale)
    page = note_html(analysis)
    parser = TagBalance()
    parser.feed(page)
    parser.close()
    assert not parser.errors and not parser.open
    markdown_tables = sum(1 for line in note_of("shaper_six_bar", locale).splitlines() if line.startswith("|---"))
    assert parser.seen["table"] == markdown_tables > 20
    assert parser.seen["html"] == parser.seen["body"] == parser.seen["title"] == 1
    assert '<meta charset="utf-8">' in page and f'<html lang="{locale}">' in page
    assert "DejaVu Sans" in page and "Noto Sans CJK" in page
    assert "V<sub>A4A3</sub>" in page and "a<sub>A4A3</sub><sup>k</sup>" in page  # the textbook's indices


def test_markdown_becomes_a_page_without_passing_raw_html_through():
    page = to_html("# Title\n\n| a | b |\n|---|---|\n| 1 | <script>x</script> |\n", "T & <t>", "en")
    assert "<table" in page and "<script>" not in page and "&lt;script&gt;" in page
    assert "<title>T &amp; &lt;t&gt;</title>" in page
    assert symbols_html("VBA = VB − VA; Group RRR; ω3, μV, R23τ, 2p5") == (
        "V<sub>BA</sub> = V<sub>B</sub> − V<sub>A</sub>; Group RRR; ω<sub>3</sub>, μ<sub>V</sub>, "
        "R<sub>23</sub><sup>τ</sup>, 2p<sub>5</sub>")
    # The dynamics' symbols, set flat in every language's HTML before (a Chinese student's reading), and words
    # that begin like them left alone.
    assert symbols_html("ΔWmax = 441.24 J, JF′ = JF·(n/n′)², Je = Σ[m·(vS/ω2)²], Md = Ar/2π; ωm, ωmax; Made Admin") == (
        "ΔW<sub>max</sub> = 441.24 J, J<sub>F′</sub> = J<sub>F</sub>·(n/n′)², J<sub>e</sub> = "
        "Σ[m·(v<sub>S</sub>/ω<sub>2</sub>)²], M<sub>d</sub> = A<sub>r</sub>/2π; ω<sub>m</sub>, ω<sub>max</sub>; "
        "Made Admin")


# The shaper's symbols that the HTML set flat: the mean reduced inertia's index ran on after a comma on the line,
# the strokes' angles, the two reactions compared, an error's two values and the friction's symbols stayed plain
# while R16 beside them took its index.
SHAPER_INDICES = {
    "en": ["J<sub>e,mean</sub>", "φ<sub>w</sub>", "φ<sub>i</sub>", "f<sub>E</sub>", "F<sub>f16</sub>",
           "M<sub>f12</sub>", "ρ<sub>O</sub>", "R<sub>16</sub>", "R<sub>12</sub>"],
    "ru": ["J<sub>п,ср</sub>", "φ<sub>р.х</sub>", "φ<sub>х.х</sub>", "R<sub>сист</sub>", "R<sub>пл</sub>",
           "X<sub>а</sub>", "X<sub>пл</sub>", "f<sub>E</sub>", "F<sub>f16</sub>", "M<sub>f12</sub>", "ρ<sub>O</sub>",
           "R<sub>16</sub>", "R<sub>12</sub>"],
}
# The same symbols written flat, as the page's text would show them where an index was missed.
FLAT = re.compile(r"(?<![\w′])(?:J[eп],|φ(?:[wi]|р\.х|х\.х)(?![\w.])|R(?:сист|пл)|X(?:а|пл)(?!\w)|f′?[A-Z]|ρ[A-Z]|"
                  r"[FM]f\d)")


@pytest.mark.parametrize("locale", ["en", "ru"])
def test_the_shapers_note_sets_every_index_below_the_line(tmp_path, locale):
    from graphplan.cli import main
    from graphplan.starters import starter

    scene = tmp_path / "shaper.toml"
    scene.write_text(starter("shaper", locale), encoding="utf-8")
    # On no sheet: the starter gives no μl, which the sheets would choose by laying themselves out at a few, and the
    # μl fitted to the field is the one they choose; note.html came out byte-identical to the scene's own (en, ru).
    (tmp_path / "light").mkdir()
    scene = on_no_sheet(scene, tmp_path / "light")
    assert main(["run", str(scene), "--out", str(tmp_path / "out"), "--only", "note,forces,dynamics"]) == 0
    page = (tmp_path / "out" / "note.html").read_text(encoding="utf-8")
    for symbol in SHAPER_INDICES[locale]:
        assert symbol in page, symbol
    text = re.sub(r"<sub>[^<]*</sub>", "", re.sub(r"<(?!/?sub>)[^>]*>", " ", page))
    assert not FLAT.findall(text), sorted(set(FLAT.findall(text)))
    # Only a symbol's letter goes before an index: no word of the note is cut into a base and an index (a group's
    # class in the structure formula, II₂(3,4), is a numeral with its order).
    # A plan's vector runs its points' letters together (ps₂, dbs₆), a short run of small Latin letters before a number.
    assert not re.findall(r"[A-Za-zА-Яа-яЁё]{2,}<sub>", re.sub(
        r"\bI{2,3}<sub>\d</sub>\(|(?<!\w)[a-zπσ]{1,2}(?=[a-zπσ]<sub>\d+</sub>(?!\w))", "", page))


def test_the_russian_dynamics_symbols_take_their_indices_below_the_line():
    """The Russian note names the flywheel's quantities as its dynamics sheet does, with Cyrillic indices; the
    words around them, and a Latin letter run on into a Russian word, stay as they are."""
    assert symbols_html("Jм = ΔTнб/(ωср²·δ) − Jп,ср; Jм′ = Jм·(n/n′)²; ΔT = Aд − Aс; Mд(ω) − Mс(φ) − Mт(ω); "
                        "Jп′(φ), mп, Fп, Mп; Машина Mсила Aдрес") == (
        "J<sub>м</sub> = ΔT<sub>нб</sub>/(ω<sub>ср</sub>²·δ) − J<sub>п,ср</sub>; J<sub>м′</sub> = "
        "J<sub>м</sub>·(n/n′)²; ΔT = A<sub>д</sub> − A<sub>с</sub>; M<sub>д</sub>(ω) − M<sub>с</sub>(φ) − "
        "M<sub>т</sub>(ω); J<sub>п′</sub>(φ), m<sub>п</sub>, F<sub>п</sub>, M<sub>п</sub>; Машина Mсила Aдрес")


def test_a_rotors_products_shares_and_planes_take_their_indices_below_the_line():
    """The balancing's m₁r₁, (m₁r₁)_L, m_i·r_i, m_L and z_R, set flat in the HTML, LaTeX and Word notes before; a
    plane named A-A, whose products are written (m·r)A-A, and words that begin like the symbols stay as they are."""
    assert symbols_html("(mi·ri)L = mi·ri·(zR − zi)/(zR − zL); Σ (mi·ri) + mb·rb = 0; (m1r1)L + (mArA)L + mLrL = 0; "
                        "mL = 1.41/0.05; (m·r)R, kg·m; m12r12; (m·r)A-A + mA-ArA-A; mere mass mark") == (
        "(m<sub>i</sub>·r<sub>i</sub>)<sub>L</sub> = m<sub>i</sub>·r<sub>i</sub>·(z<sub>R</sub> − z<sub>i</sub>)/"
        "(z<sub>R</sub> − z<sub>L</sub>); Σ (m<sub>i</sub>·r<sub>i</sub>) + m<sub>b</sub>·r<sub>b</sub> = 0; "
        "(m<sub>1</sub>r<sub>1</sub>)<sub>L</sub> + (m<sub>A</sub>r<sub>A</sub>)<sub>L</sub> + m<sub>L</sub>r<sub>L</sub>"
        " = 0; m<sub>L</sub> = 1.41/0.05; (m·r)<sub>R</sub>, kg·m; m<sub>12</sub>r<sub>12</sub>; "
        "(m·r)A-A + mA-ArA-A; mere mass mark")


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_the_rotors_note_sets_its_balancing_notation_as_the_textbook_does(tmp_path, locale):
    from graphplan.cli import main
    from graphplan.starters import starter

    scene = tmp_path / "rotor.toml"
    scene.write_text(starter("rotor", locale), encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "out"), "--only", "note,balancing"]) == 0
    page = (tmp_path / "out" / "note.html").read_text(encoding="utf-8")
    for symbol in ("(m<sub>i</sub>·r<sub>i</sub>)<sub>L</sub>", "(m<sub>1</sub>r<sub>1</sub>)<sub>R</sub>",
                   "m<sub>L</sub>r<sub>L</sub>", "z<sub>R</sub>", "(m·r)<sub>L</sub>"):
        assert symbol in page, symbol
    text = re.sub(r"<sub>[^<]*</sub>", "", re.sub(r"<(?!/?sub>)[^>]*>", " ", page))
    assert not re.findall(r"\bm\d+r\d+|\bm[LRb]r[LRb]\b|\bz[LRi]\b|\)[LR]\b", text)
    latex = (tmp_path / "out" / "note.tex").read_text(encoding="utf-8")
    assert r"(m\textsubscript{1}r\textsubscript{1})\textsubscript{L}" in latex


# Determinism.

def test_the_note_is_the_same_every_time():
    scene = graphplan.load(FIXTURES / "tangent_mechanism_prp.toml")
    first, second = analyse(scene), analyse(dataclasses.replace(scene))
    assert note_markdown(first) == note_markdown(second) == note_markdown(first)
    assert note_html(first) == note_html(second)


def test_a_scene_without_loads_or_plans_still_gets_its_note():
    scene = graphplan.load(FIXTURES / "ratchet_crank_rocker.toml")
    bare = analyse(dataclasses.replace(scene, links={}, loads=()))
    note = note_markdown(bare)
    assert "Силовой" not in note and "Погрешности планов" in note
    no_plans = analyse(dataclasses.replace(scene, positions=dataclasses.replace(scene.positions, plans=()),
                                           measured={}))
    note = note_markdown(no_plans)
    # A crank's balancing load is its balancing moment, as a Russian note names it.
    assert "План скоростей" not in note and "Уравновешивающий момент за цикл" in note


def test_the_note_works_out_each_friction_load_and_checks_them_on_the_lever():
    """ρ = f·r and Mf = ρ·R of each journal, Ff = f′·N of each slide, at the settled reactions, are the loads
    the polygons with friction were closed with; the lever with them gives the polygons' Mb."""
    from test_lever_with_friction import slotted_lever_with_friction

    analysis = slotted_lever_with_friction()
    note = note_markdown(analysis)

    def n(value):
        return force_report.number(value, 5)

    for plan in analysis.plans:
        rubbing = plan.with_friction
        used = {load.name: load for group in rubbing.groups for load in group.loads}
        for pair in analysis.friction:
            reaction = abs(rubbing.reactions[pair.reaction].force)
            name = f"{'Ff' if pair.sliding else 'Mf'}{pair.source}{pair.target}"
            factor = pair.coefficient if pair.sliding else pair.radius
            load = used[name]
            assert abs(load.force if pair.sliding else load.moment) == pytest.approx(factor * reaction, rel=1e-9)
            # The slot and the crank pin are both at A: each is named by its links, f34 and ρ23 (a flat slot's
            # coefficient is f as given, not a reduced f′).
            at = pair.joint if [p.joint for p in analysis.friction].count(pair.joint) == 1 else f"{pair.source}{pair.target}"
            symbol = f"f{at}" if pair.sliding else f"ρ{at}"
            # The reaction is written to as many digits as make the printed product read the load as printed.
            written = re.search(rf"{name} = {symbol}·{pair.reaction} = {re.escape(n(factor))}·([\d.]+) = "
                                rf"{re.escape(n(factor * reaction))}(?![\d.])", note)
            assert written, name
            assert float(written[1]) == pytest.approx(reaction, rel=1e-4)
            assert n(factor * float(written[1])) == n(factor * reaction)
            if not pair.sliding:
                assert f"ρ{at} = f·r = {n(pair.spec.f)}·{n(pair.spec.radius)} = {n(pair.radius)} m" in note
        lever = plan.lever_with_friction.balancing
        assert lever == pytest.approx(rubbing.balancing, rel=1e-9)
        # Worked as the lever without friction is, after its own table: |Mb| = Fb·lOA = … N·m.
        caption = strings("en")["note_friction_lever_table"].format(number=plan.number)
        worked = note.split(caption, 1)[1].split("![", 1)[0]
        assert f"= {force_report.number(abs(lever), 6)} N·m" in worked


@pytest.mark.parametrize("given", [True, False])
def test_the_initial_data_give_the_length_scale_the_plan_of_positions_is_drawn_at(given):
    """μl stands among the initial data whether the scene gives it or the program chooses it for the sheets
    (the shaper without μl on A1 is drawn a step smaller than its 200 mm field to save a sheet): the value
    is the one the plan of positions writes under its title."""
    from graphplan.render.drawings import positions_svg

    scene = graphplan.load(FIXTURES / "shaper_six_bar.toml")
    if not given:
        scene = dataclasses.replace(scene, drawing=dataclasses.replace(scene.drawing, length_scale=None))
    analysis = analyse(scene)
    drawn = re.search(r"μl = ([\d.]+) m/mm", flat(positions_svg(analysis))).group(1)
    stated = re.search(r"^\| μl \| ([\d.]+) m/mm \|", note_markdown(analysis), re.MULTILINE).group(1)
    assert stated == drawn
    assert (float(drawn) == scene.drawing.length_scale) if given else float(drawn) > 0.0025


@pytest.mark.parametrize("locale", LOCALES)
def test_the_initial_data_give_the_frame_from_which_the_mechanism_is_drawn(locale):
    """The shaper's frame: its pivots O and C, the ram's guide a horizontal line 0.64 m above C.  The initial data
    must say how far apart the pivots are and where the guide runs, or the reader cannot draw the mechanism."""
    scene = tomllib.loads((FIXTURES / "shaper_six_bar.toml").read_text(encoding="utf-8"))["frame"]
    (c_x, c_y), (o_x, o_y) = scene["points"]["C"], scene["points"]["O"]
    guide_y = scene["lines"]["ram"]["through"][1]
    note = note_of("shaper_six_bar", locale)
    mark = "," if locale == "ru" else "."
    between = f"{math.hypot(o_x - c_x, o_y - c_y):g}".replace(".", mark)
    assert re.search(rf"^\| lOC \| {re.escape(between)} (m|м) \|$", note, re.MULTILINE)
    above = f"{abs(guide_y - o_y):g}".replace(".", mark)
    (row,) = [line for line in note.splitlines() if line.startswith("| ram |")]
    value = row.split("|")[2]
    assert above in value and "O" in value and "0°" in value


@pytest.mark.parametrize("locale", LOCALES)
def test_a_speed_given_in_rpm_is_among_the_initial_data_with_omega_worked_out_from_it(locale):
    """The engine's crank turns at 1500 rpm: the note gave only ω2 = 157.08 rad/s, and the reader could not see
    the assignment's n in it.  A speed given as ω stays as it is, with no n."""
    unit = {"en": "rpm", "ru": "об/мин", "zh": "r/min"}[locale]
    rows = dict(table_after(note_of("engine_slider_crank", locale), {"en": "Table 2", "ru": "Таблица 2",
                                                                     "zh": "表 2"}[locale]))
    assert rows["n2"] == f"1500 {unit}"
    omega = re.fullmatch(r"πn2/30 = π[·×]1500/30 = ([\d.,]+) .*", rows["ω2"]).group(1)
    assert agrees(omega, math.pi * 1500 / 30) and agrees(omega, analysis_of("engine_slider_crank", locale)
                                                          .mechanism.driver.omega)
    ratchet = note_of("ratchet_crank_rocker", locale)
    assert "| ω2 | " in ratchet and "| n2 |" not in ratchet and "πn2/30" not in ratchet


def test_the_speed_in_rpm_and_the_points_take_their_indices_below_the_line():
    assert symbols_html("n2") == "n<sub>2</sub>"
    # A plan's points as the drawings letter them (n₄, s₂, σ₆), in the vectors that run them together; a number is
    # none, and the arm of an inertia force is h with u₄ below, as the drawings set it, not the vector from h to u₄.
    assert symbols_html("πn2/30 = π·1500/30; ⊥ CB через n4; πn4 = 2,99; n4b; ps2·μV; b4k5; pσ6; n6′; 1e2; hu4") == (
        "πn<sub>2</sub>/30 = π·1500/30; ⊥ CB через n<sub>4</sub>; πn<sub>4</sub> = 2,99; n<sub>4</sub>b; "
        "ps<sub>2</sub>·μ<sub>V</sub>; b<sub>4</sub>k<sub>5</sub>; pσ<sub>6</sub>; n<sub>6</sub>′; 1e2; h<sub>u4</sub>")
    # A mechanism's point alone, as the drawings letter it (A₄, Σ₆, S₂′); an integrator's name is none.
    assert symbols_html("A4 is the point of link 4; Σ6 moves; S2′; L − L0; RK45, DOP853") == (
        "A<sub>4</sub> is the point of link 4; Σ<sub>6</sub> moves; S<sub>2</sub>′; L − L<sub>0</sub>; RK45, DOP853")


def test_a_point_placed_on_another_has_no_length_among_the_initial_data():
    """The rocker's centre of mass put on its pivot (at = 0): lCS4 = 0 is no dimension of the link."""
    text = (FIXTURES / "ratchet_crank_rocker.toml").read_text(encoding="utf-8")
    moved = re.sub(r'^S4 = \{ link = 4, from = "C", toward = "B", at = [\d.]+ \}', 'S4 = { link = 4, from = "C", '
                   'toward = "B", at = 0.0 }', text, flags=re.MULTILINE)
    assert moved != text
    lengths = re.findall(r"^\| (l[A-Z]\w*) \|", note_markdown(analyse(graphplan.scene.loads(moved))), re.MULTILINE)
    assert "lCS4" not in lengths and {"lOA", "lAB", "lCB", "lOC"} <= set(lengths)


@pytest.mark.parametrize(("name", "joint", "distance", "angle"), [
    ("engine_slider_crank", "B", 0.0, 0.0),                  # the cylinder's axis through the crank's pivot
    ("scotch_yoke", "B", 0.0, 90.0),                         # the yoke's vertical guide through O
    ("triad_with_slider", "F", 0.14 * math.cos(math.radians(30.0)), -30.0),  # through E = (0, 0.14) at −30°
])
def test_a_guide_given_in_its_group_is_among_the_frame_s_data(name, joint, distance, angle):
    """A frame guide written in its group rather than among [frame] lines is given as the line its slider's joint
    runs along: its distance from the crank's pivot O (worked out here from the fixture's coordinates) and its angle."""
    # The scene's own title in place of note_of's stands in the note's head alone, nowhere near its frame's data.
    note = note_of(name, "en") if name in KINDS else unsheeted_note(name, "en")
    (row,) = [line for line in note.splitlines() if line.startswith(f"| guide of {joint} |")]
    value = row.split("|")[2]
    found = re.fullmatch(r" ([\d.]+) m from O, at (−?[\d.]+)° to x ", value)
    assert found, value
    assert float(found.group(1)) == pytest.approx(distance, abs=5e-6)
    assert float(found.group(2).replace("−", "-")) == pytest.approx(angle)


def test_a_named_guide_is_given_once_though_its_slider_starts_on_the_pivot():
    """The scotch yoke's guide named among [frame] lines, the crank started at 0° so that the yoke's B stands on O:
    the line is given once, by its name, not again as the line B runs along."""
    text = (FIXTURES / "scotch_yoke.toml").read_text(encoding="utf-8")
    text = text.replace("points = { O = [0.0, 0.0] }",
                        'points = { O = [0.0, 0.0] }\nlines = { yoke = { through = "O", angle = 90.0 } }')
    text = re.sub(r"^guide  = \{ through = \[0.0, 0.0\], angle = 90.0 \}", 'guide = "yoke"', text, flags=re.MULTILINE)
    text = re.sub(r"^start *= .*$", "start = 0.0", text, flags=re.MULTILINE)
    analysis = analyse(graphplan.scene.loads(text))
    assert abs(analysis.motion.points["B"].r[0]) < 1e-12
    rows = [line for line in note_markdown(analysis).splitlines() if line.startswith(("| yoke |", "| guide of"))]
    assert rows == ["| yoke | 0 m from O, at 90° to x |"]


# A crank OA driving a slotted lever about C whose slide misses C by the offset.
OFFSET_SLOTTED_LEVER = """
[scene]
title = "Slotted lever with an offset slide"

[frame]
link = 1
points = { O = [0.0, 0.0], C = [0.0, -0.25] }

[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = 0.1
omega = 10.0

[[groups]]
kind = "RPR"
links = [3, 4]
joints = ["A", "C"]
offset = OFFSET

[positions]
count = 12
start = 0.0
plans = [2]
"""


@pytest.mark.parametrize("offset", [0.02, -0.03])
def test_an_rpr_slide_that_misses_the_levers_pivot_is_among_the_initial_data(offset):
    """The offset defines the mechanism, yet the table left it out: it says how far the slide passes from the pivot C
    and on which side, standing at C and facing the block's pin A (worked out here from the closure
    A = C + (s + i·e)·u, the slide's foot from C at i·e·u)."""
    analysis = analyse(graphplan.scene.loads(OFFSET_SLOTTED_LEVER.replace("OFFSET", repr(offset))))
    a, c = complex(np.ravel(analysis.motion.points["A"].r)[0]), -0.25j
    s = math.sqrt(abs(a - c) ** 2 - offset**2)
    u = (a - c) / complex(s, offset)
    foot = c + 1j * offset * u
    towards = a - c
    side = "left" if towards.real * (foot - c).imag - towards.imag * (foot - c).real > 0 else "right"
    rows = [line for line in note_markdown(analysis).splitlines() if line.startswith("| slide of link 4 |")]
    assert rows == [f"| slide of link 4 | {abs(foot - c):g} m from C, on the {side} seen from C toward A |"]
    assert side == ("left" if offset > 0 else "right")


def test_a_slide_through_the_levers_pivot_adds_no_row():
    analysis = analyse(graphplan.scene.loads(OFFSET_SLOTTED_LEVER.replace("OFFSET", "0.0")))
    assert "slide of link" not in note_markdown(analysis)


INVERTED_SLIDER_CRANK = """
[scene]
title = "Inverted slider-crank: the block slides on the crank"

[frame]
link = 1
points = { O = [0.0, 0.0], C = [0.2, 0.05] }

[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = 0.1
omega = 10.0

[[groups]]
kind = "RRP"
links = [3, 4]
joints = ["C", "B"]
length = 0.35
guide = { link = 2, through = "A", angle = 30.0 }
assembly = "forward"

[positions]
count = 12
start = 0.0
plans = [3]
"""


@pytest.mark.parametrize("locale", LOCALES)
def test_a_guide_on_a_moving_link_is_among_the_initial_data(locale):
    """The block B slides on a guide of the crank through A at 30° to OA, and the table did not list it at all.
    The angle is checked on the motion: seen from the crank, B runs on the line through A at 30° to OA."""
    scene = dataclasses.replace(graphplan.scene.loads(INVERTED_SLIDER_CRANK), locale=locale)
    analysis = analyse(scene)
    o, a, b = (np.broadcast_to(analysis.motion.points[name].r, (12,)) for name in ("O", "A", "B"))
    seen_from_crank = np.degrees(np.angle((b - a) / (a - o))) % 180.0
    assert seen_from_crank == pytest.approx(np.full(12, 30.0), abs=1e-9)
    expected = {"en": "| guide of B | through A, at 30° to OA |",
                "ru": "| направляющая точки B | через A, под углом 30° к OA |",
                "zh": "| B 的导路 | 过 A，与 OA 成 30° |"}[locale]
    assert expected in note_markdown(analysis).splitlines()


@pytest.mark.parametrize("locale", LOCALES)
def test_an_rpp_slot_angle_is_among_the_initial_data(locale):
    """The Scotch yoke's slot set at 60° to its guide, which defines the mechanism as much as a length, was in no row.
    The angle is read off the motion: the block turns with the slot, link b with the guide."""
    text = (FIXTURES / "scotch_yoke.toml").read_text(encoding="utf-8")
    text = re.sub(r"(?m)^angle  = 90\.0 ", "angle  = 60.0 ", text)
    analysis = analyse(dataclasses.replace(graphplan.scene.loads(text), locale=locale))
    slot, guide = (np.ravel(analysis.motion.link(link).angle)[0] for link in (3, 4))
    assert math.degrees(slot - guide) % 360.0 == pytest.approx(60.0)
    expected = {"en": "| slot of link 4 | at 60° to the guide of B, counter-clockwise from the guide |",
                "ru": "| паз звена 4 | под углом 60° к направляющей точки B, против часовой стрелки от неё |",
                "zh": "| 构件 4 上的导槽 | 与 B 的导路成 60°，自导路逆时针量取 |"}[locale]
    assert expected in note_markdown(analysis).splitlines()


@pytest.mark.parametrize("offset", [0.03, -0.02])
def test_a_prp_joint_beside_a_guide_on_a_moving_link_is_among_the_initial_data(offset):
    """The tangent mechanism's block B runs 30 mm beside the lever's slot line CA; the table gave the slot's line and
    not the offset.  The side is checked on the motion: B stands |offset| from the line CA, on the left of C→A for a
    positive offset."""
    text = (FIXTURES / "tangent_mechanism_prp.toml").read_text(encoding="utf-8")
    text = text.replace("offsets = [0.0, 0.0]", f"offsets = [{offset!r}, 0.0]")
    analysis = analyse(dataclasses.replace(graphplan.scene.loads(text), locale="en"))
    a, b = (complex(np.ravel(analysis.motion.points[name].r)[0]) for name in ("A", "B"))
    along = a / abs(a)  # C is the origin
    beside = along.real * b.imag - along.imag * b.real
    assert abs(beside) == pytest.approx(abs(offset)) and (beside > 0) == (offset > 0)
    side = "left" if offset > 0 else "right"
    assert f"| slide of link 5 | {abs(offset):g} m from the guide of B, on its {side} seen along it |" in (
        note_markdown(analysis).splitlines())


def test_a_point_off_the_line_it_is_placed_from_is_given_from_both_ends_of_that_line():
    """The rocker CB carries a third joint D, the coupler AB a point M, each set off its line: the table gave lCD and
    lAM only, though the similarity proportions read lBD and lBM.  Both follow from the scene's numbers: a point `at`
    along a line of length l and `offset` off it is sqrt((l − at)² + offset²) from the line's far end."""
    text = (FIXTURES / "ratchet_crank_rocker.toml").read_text(encoding="utf-8")
    scene = tomllib.loads(text)
    rrr = next(group for group in scene["groups"] if group["kind"] == "RRR")
    ab, cb = rrr["lengths"]
    points = {"D": ("C", "B", cb, 0.25 * cb, 0.06), "M": ("A", "B", ab, 0.6 * ab, -0.04)}
    lines = [f'{name} = {{ link = {3 if start == "A" else 4}, from = "{start}", toward = "{toward}", '
             f'at = {at!r}, offset = {offset!r} }}' for name, (start, toward, _, at, offset) in points.items()]
    text = re.sub(r"(?m)^\[points\]$", "[points]\n" + "\n".join(lines), text)
    note = note_markdown(analyse(dataclasses.replace(graphplan.scene.loads(text), locale="en")))
    lengths = dict(re.findall(r"^\| (l[A-Z]\w*) \| ([\d.]+) m \|$", note, re.MULTILINE))
    for name, (start, toward, length, at, offset) in points.items():
        assert float(lengths[f"l{start}{name}"]) == pytest.approx(math.hypot(at, offset), rel=5e-5)
        assert float(lengths[f"l{toward}{name}"]) == pytest.approx(math.hypot(length - at, offset), rel=5e-5)


def test_a_link_at_rest_in_its_extreme_position_has_no_sense_of_turning():
    """At the crank-rocker's extreme ω4 is rounding's 1e-16, written 0: the note said "0 rad/s, clockwise"."""
    from graphplan.starters import starter

    text = re.sub(r"(?m)^plans\s*=.*$", "plans = [0]", starter("crank-rocker"))
    analysis = analyse(graphplan.scene.loads(text))
    assert abs(analysis.motion.link(4).omega[0]) < 1e-9 and analysis.positions.numbers[0] == 0
    line = next(line for line in note_markdown(analysis).splitlines() if line.startswith("- ω4 = "))
    assert line.endswith(" = 0 rad/s"), line


def test_a_working_stroke_slower_than_the_idle_one_gets_no_remark_on_k():
    note = note_of("shaper_six_bar", "en")
    assert re.search(r"K = φw/φi = 1\.\d+\.", note) and "K < 1" not in note


@pytest.mark.parametrize(("name", "load", "other"), [("ratchet_crank_rocker", "Уравновешивающий момент Mу", "сила Fу"),
                                                     ("slider_driven", "Уравновешивающая сила Fу", "момент Mу")])
def test_a_russian_note_names_the_balancing_load_a_moment_or_a_force_as_the_driver_takes_it(name, load, other):
    """«Уравновешивающая нагрузка Mb» for a crank read as a generic word where the course says «момент»."""
    note = note_of(name, "ru")
    forces = force_report.markdown(analysis_of(name, "ru"))
    assert load in note and load in forces
    assert "Уравновешивающая нагрузка" not in note + forces and f"Уравновешивающая {other}" not in note


def test_a_slides_reaction_with_no_couple_is_said_to_pass_through_its_joint():
    """The shaper's ram 6 and block 3 carry no moment about their joints: the note wrote «R16·x = 0 ⇒ R16·x = 0
    N·m», which says nothing; the offsets in results.json are nought."""
    analysis = analysis_of("shaper_six_bar", "en")
    note = note_of("shaper_six_bar", "en")
    for position in analysis.plans:
        offsets = {name: found.offset for name, found in position.forces.reactions.items()}
        assert offsets["R16"] == pytest.approx(0.0, abs=1e-9)
    assert "- ΣME(6) = R16·x = 0 ⇒ x = 0: the line of R16 passes through E" in note
    assert "⇒ R16·x = 0" not in note


def test_a_chinese_note_s_friction_loads_join_their_formulas_with_the_full_width_semicolon():
    """ρO = f·r and Mf12 = ρO·R12 (f′ and Ff of a slide) stood joined by a Latin "; " in the Chinese note, whose other
    formulas the locale's "；" joins."""
    from graphplan.run import as_asked
    from graphplan.scene import loads as scene_from_text
    from graphplan.starters import starter

    scene = scene_from_text(starter("shaper", "zh"))
    # On no sheet: the friction's lines are the same whatever sheet the drawings go on, and the note's scale for
    # its sheets is chosen by laying them all out (the Chinese shaper's note on its sheet is made by
    # test_note_names_no_files_or_keys).
    note = note_markdown(analyse(as_asked(scene, sheet="none")))
    journal = next(spec for spec in scene.friction if spec.radius is not None)
    slide = next(spec for spec in scene.friction if spec.radius is None)
    rubbing = [line for line in note.splitlines() if line.startswith(("- ρ", "- f"))]
    assert rubbing and not any("; " in line for line in rubbing)
    rho = force_report.number(journal.f * journal.radius)
    assert any(f"= {rho} m；Mf" in line for line in rubbing)
    assert any(line.startswith(f"- f{slide.joint} = {force_report.number(slide.f)}；Ff") for line in rubbing)


@pytest.mark.parametrize("locale", LOCALES)
def test_a_slider_driven_backward_keeps_the_sign_of_its_rate_and_gives_the_modulus(locale):
    """The rod driven back along its cylinder (ṡ = −0.08 m/s, s̈ = −0.02 m/s²): the note wrote VA = ṡ = 0.08 m/s
    along its guide, a positive ṡ where the table of data gives −0.08.  It writes the signed rate, then the modulus
    of the vector, which points against the guide; the vector's length is checked on the analytic motion."""
    text = (FIXTURES / "slider_driven.toml").read_text(encoding="utf-8")
    text = re.sub(r"(?m)^velocity( *)= 0\.08", r"velocity\1= -0.08", text)
    text = re.sub(r"(?m)^acceleration( *)= 0\.0 ", r"acceleration\1= -0.02 ", text)
    scene = dataclasses.replace(graphplan.scene.loads(text), locale=locale)
    analysis = analyse(scene)
    guide = 1.0 + 0j  # the cylinder's axis, along +x
    v_a = complex(np.ravel(analysis.motion.points["A"].v)[0])
    a_a = complex(np.ravel(analysis.motion.points["A"].a)[0])
    assert (v_a / guide).real == pytest.approx(-0.08) and (a_a / guide).real == pytest.approx(-0.02)
    mark = "," if locale == "ru" else "."
    speed, rate = f"{abs(v_a):g}".replace(".", mark), f"{abs(a_a):g}".replace(".", mark)
    unit = {"ru": ("м/с", "м/с²")}.get(locale, ("m/s", "m/s²"))
    note = note_markdown(analysis)
    assert f"ṡ = −{speed} {unit[0]}" in note and f"VA = |ṡ| = {speed} {unit[0]}" in note
    assert f"s̈ = −{rate} {unit[1]}" in note and f"aA = |s̈| = {rate} {unit[1]}" in note
    assert "VA = ṡ" not in note and "aA = s̈" not in note
    against = {"en": "against the direction of its guide", "ru": "противоположную её положительному направлению",
               "zh": "与导路的正向相反"}[locale]
    assert note.count(against) == 2 * len(analysis.plans)



def test_a_russian_note_names_each_group_s_kind_grammatically():
    """«Группа III(3,4,5,6), вид трёхповодковая»: an adjective with no noun, in a heading of the note (a hunt's
    triad).  The kind stands after «вид:» as a name, the triad's with its noun, a dyad's by its pairs."""
    triad = unsheeted_note("triad_class_iii", "ru")
    assert re.search(r"\*\*Группа III\S*, вид: трёхповодковая группа\*\*", triad)
    assert "вид трёхповодковая" not in triad
    dyads = re.findall(r"\*\*Группа II(?!I)\S*, вид: (\S+)", note_of("ratchet_crank_rocker", "ru"))
    assert dyads and all(set(kind) <= set("ВП") for kind in dyads)
