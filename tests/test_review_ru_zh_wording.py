"""The Russian and Chinese texts as a teacher of the theory of machines reads them: the textbooks' terms and
notation, the facts a term states, and each language's punctuation.

Found on a review of every fixture and starter in ru and zh: the Chinese structure table gave the class III triad
«3 个构件» (it has four links; its order 3 counts its outer pairs) and headed it «Ⅲ级杆组 型»; Chinese table headers
and errors.md set ASCII commas, semicolons and a space after «。» beside Chinese words; the Chinese dynamics wrote
ΔT once where all else writes ΔE; a Russian force sheet wrote the friction angle «arctan f» where Russian writes
arctg (as the note's tg φ); «интегрирование даёт 0,0235 с учётом» read as 0.0235 seconds; a slider driver's note
named its balancing force twice, «the balancing force on the lever and the balancing force».
"""

from __future__ import annotations

import dataclasses
import re
from pathlib import Path
from xml.etree import ElementTree

import pytest
from test_joint_friction import slider_crank
from test_note_dynamics import KLOSS, machine_note

from graphplan.analysis import analyse
from graphplan.locale import strings
from graphplan.mechanism import build
from graphplan.render.drawings import with_length_scale
from graphplan.report import forces as force_report
from graphplan.report import tables
from graphplan.run import run as run_scene
from graphplan.scene import load
from graphplan.starters import starter

ROOT = Path(__file__).resolve().parent.parent
FIXTURES = ROOT / "fixtures"
CJK = "\u4e00-\u9fff"


def note_of(scene_path: Path, out: Path, locale: str, only=("note",)) -> str:
    scene = dataclasses.replace(load(scene_path), locale=locale)
    run_scene(scene, out, only=list(only), sheet="none")
    return (out / "note.md").read_text(encoding="utf-8")


def test_the_chinese_structure_table_counts_a_triad_s_outer_pairs_and_names_its_kind_once(tmp_path):
    """A group's order is the number of its outer pairs, the joints it shares with links outside it: the triad's
    four links meet the crank and the frame at three (A, C, E), which the Chinese table had written as 3 links."""
    path = FIXTURES / "triad_class_iii.toml"
    note = note_of(path, tmp_path / "out", "zh")
    mechanism = build(load(path))
    for group in mechanism.groups:
        outside = [link for link in mechanism.fixed_on if link not in group.links]
        outer = {joint for joint in group.joints if any(joint in mechanism.fixed_on[link] for link in outside)}
        row = next(line for line in note.splitlines() if line.startswith(f"| {group.label} |"))
        cells = [cell.strip() for cell in row.strip("|").split("|")]
        found = re.fullmatch(r"(I+) 级杆组（(\d+) 个外副）", cells[1])
        assert found, row
        assert found.group(1) == "I" * group.klass and int(found.group(2)) == len(outer) == 3
        assert len(cells[2].split(", ")) == len(group.links) == 4
        # The heading names the kind after «类型：», not «Ⅲ级杆组 型» (a kind with a type word after it).
        assert f"**杆组 {group.label}，类型：III 级杆组**" in note
    assert "个构件" not in note and " 型**" not in note
    assert "Ⅲ" not in note  # one way of writing a Roman numeral, as the class column writes it
    # The two lines that close the triad's polygon, listed in a Chinese sentence, take its enumeration comma.
    closing = re.findall(r"然后由 (\S*) 的作用线封闭力多边形", note)
    assert closing and all(re.fullmatch(r"R\d+n、R\d+n", pair) for pair in closing), closing


@pytest.fixture(scope="module")
def chinese_shaper(tmp_path_factory):
    """The shaper starter in Chinese (friction in its pairs, a flywheel and a motor): its note and errors.md."""
    folder = tmp_path_factory.mktemp("shaper-zh")
    scene = folder / "shaper.toml"
    scene.write_text(starter("shaper", "zh"), encoding="utf-8")
    written = run_scene(load(scene), folder / "out", only=["note", "errors", "dynamics"], sheet="none")
    files = {name: (folder / "out" / name).read_text(encoding="utf-8") for name in ("note.md", "errors.md")}
    # forces.md as the run writes it with the forces (their sheets left undrawn: their layout is not the words')
    return {**files, "forces.md": force_report.markdown(written.analysis)}


def test_chinese_tables_and_errors_md_set_full_width_punctuation_beside_chinese_words(chinese_shaper):
    note, errors, forces = chinese_shaper["note.md"], chinese_shaper["errors.md"], chinese_shaper["forces.md"]
    headers = [line for text in (note, errors, forces) for line in text.splitlines()
               if line.startswith("|") and re.search(f"[{CJK}]", line)]
    assert headers
    for line in headers:
        assert not re.search(f"[{CJK}][,;] ", line), line  # «长度, mm», «数值, N ∠»
        assert not re.search(rf"[{CJK}]\)| \([{CJK}]", line), line  # «Je, kg·m² (图解值)»
    assert "| 线段 | 长度，mm |" in note and "数值，N ∠" in note and "Je, kg·m²（图解值）" in note
    assert "| 反力，N | 摩擦载荷 |" in forces and "| 力多边形，N ∠ | 平衡方程组，N ∠ |" in forces
    prose = [line for line in errors.splitlines() if line and not line.startswith(("|", "#"))]
    assert prose
    for line in prose:
        assert not re.search(r"[。；：，] ", line), line  # «比较。 运动副有摩擦时»
        assert not re.search(f"; [{CJK}]", line), line  # «× 100 %; 量取»
    # Each of the two sentences the reactions' paragraph joins is there, set close.
    assert "结果比较。运动副有摩擦时" in errors


def test_the_chinese_dynamics_writes_the_change_of_kinetic_energy_as_its_drawings_do(chinese_shaper):
    note = chinese_shaper["note.md"]
    dynamics = note[note.index(f"## 6 {strings('zh')['note_dynamics']}"):]
    assert "ΔE = Wd − Wr" in dynamics and "ΔE 和飞轮" in dynamics
    assert "ΔT" not in note


def test_the_chinese_note_names_the_coefficient_delta_as_its_flywheel_is_worked_out(chinese_shaper):
    """δ, the coefficient the flywheel is sized for, is 速度不均匀系数 where the dynamics works the flywheel out and in
    the textbooks; the conclusion had named it 速度波动系数, another quantity's name to a reader of both."""
    note = chinese_shaper["note.md"]
    zh = strings("zh")
    ends = re.search(rf"^## \d+ {zh['note_conclusion']}$", note, re.MULTILINE)
    dynamics, conclusion = note[note.index(f" {zh['note_dynamics']}\n"):ends.start()], note[ends.start():]
    worked = re.search(r"(速度\w{1,4}系数) δ = ", dynamics)
    assert worked and worked.group(1) == "速度不均匀系数"
    named = re.findall(r"速度\w{1,4}?系数", conclusion)
    assert named and set(named) == {worked.group(1)}, named


def test_the_chinese_note_sets_the_balancing_load_s_symbol_apart_from_its_name(chinese_shaper):
    note = chinese_shaper["note.md"]
    assert "四种方法求得的平衡力矩 Mb" in note and "各位置的平衡力矩 Mb" in note
    assert not re.search("平衡力矩?[A-Za-z]", note)


def test_a_russian_force_sheet_writes_the_friction_angle_with_arctg(tmp_path):
    """Russian writes tg and arctg (the note's vibration: tg φ = …); the slide's friction angle read arctan f."""
    from test_slide_friction_on_the_sheet import caption_of

    scene = slider_crank('[[friction]]\njoint = "B"\nlinks = [1, 4]\nf = 0.1')
    for locale, written in (("ru", "arctg"), ("zh", "arctan"), ("en", "arctan")):
        analysis = with_length_scale(analyse(dataclasses.replace(scene, locale=locale)))
        for position in analysis.plans:
            caption = caption_of(analysis, position)
            found = re.search(r"φ = (\w+) f = ([\d.,]+)°", caption)
            assert found and found.group(1) == written, caption
            assert float(found.group(2).replace(",", ".")) == pytest.approx(5.711, abs=1e-3)  # atan 0.1 in degrees


def test_the_russian_integrated_delta_is_not_read_as_seconds(tmp_path):
    """«интегрирование даёт 0,0235 с учётом…»: a number followed by «с» reads as seconds in a Russian text."""
    note = machine_note(tmp_path, KLOSS, "ru")[0]
    line = next(line for line in note.splitlines() if line.startswith("Маховик рассчитан"))
    found = re.search(r"интегрирование даёт δ = (\d+,\d+)\.$", line)
    assert found, line
    steady = re.search(r"δ = \(ωmax − ωmin\)/ωср = (\d+,\d+)", note)
    assert steady and steady.group(1) == found.group(1)
    assert not re.search(r"\d с учётом", note)


def test_the_russian_load_diagram_says_what_its_ring_marks_in_the_note_s_terms(tmp_path):
    out = tmp_path / "out"
    scene = dataclasses.replace(load(FIXTURES / "engine_slider_crank.toml"), locale="ru")
    run_scene(scene, out, only=["load_diagrams", "note"], sheet="none")
    drawn = [" ".join(element.itertext()) for element in ElementTree.parse(out / "load_diagrams.svg").iter()
             if element.tag.endswith("}text")]
    legend = strings("ru")["ld_plans"]
    assert legend in drawn
    # The note calls those sheets «листы силового расчёта»; the legend had «лист сил положения плана».
    assert "листы силового расчёта" in (out / "note.md").read_text(encoding="utf-8")
    assert "силового расчёта" in legend and not any("лист сил " in text for text in drawn)


def test_the_russian_friction_reactions_sentence_reads_as_russian(tmp_path):
    scene = slider_crank('[[friction]]\njoint = "A"\nlinks = [2, 3]\nf = 0.1\nradius = 0.01')
    analysis = analyse(dataclasses.replace(scene, locale="ru"))
    written = force_report.markdown(analysis)
    # Once for each position whose friction settles: «…с решением всех уравнений равновесия с трением совместно:»
    # left «совместно» hanging at the sentence's end.
    said = ("Реакции с учётом трения по планам сил с трением в сравнении с совместным решением всех уравнений "
            "равновесия с трением:")
    assert written.count(said) == len(analysis.plans) > 0
    assert "совместно:" not in written


@pytest.mark.parametrize("locale, words", [("ru", "уравновешивающ"), ("zh", "平衡力"), ("en", "balancing")])
def test_a_slider_driver_s_lever_names_its_balancing_force_once(tmp_path, locale, words):
    """The lever's force of a slider driver is its balancing force: «Уравновешивающая сила на рычаге и
    уравновешивающая сила: Fb = …; Fb = …» named one force twice as if two."""
    note = note_of(FIXTURES / "slider_driven.toml", tmp_path / "out", locale)
    lines = [line for line in note.splitlines() if line.startswith(("Уравновешивающая сила на рычаге",
                                                                    "杠杆上的平衡力", "Balancing force on the lever"))]
    assert lines
    for line in lines:
        assert line.lower().count(words) == 1, line
        # The Russian textbook's Fу (уравновешивающая), as the Russian lever drawing names it.
        assert re.search(f"{'Fу' if locale == 'ru' else 'Fb'}" r" = \|Σ\(F·h\)\|/pa = ", line), line
    assert len(lines) == len(analyse(load(FIXTURES / "slider_driven.toml")).plans)


def test_a_crank_s_lever_still_gives_the_balancing_moment_beside_the_force(chinese_shaper):
    lines = [line for line in chinese_shaper["note.md"].splitlines() if line.startswith("杠杆上的平衡力")]
    assert lines and all(line.startswith("杠杆上的平衡力及平衡力矩：Fb = ") and "|Mb| = Fb·lOA" in line for line in lines)


def test_errors_md_of_every_language_keeps_its_own_semicolon(tmp_path):
    scene = load(FIXTURES / "engine_slider_crank.toml")
    for locale, joined in (("en", "; "), ("ru", "; "), ("zh", "；")):
        text = strings(locale)
        written = tables.markdown(analyse(dataclasses.replace(scene, locale=locale)))
        assert f"{text['errors_formula']}{joined}" in written


def test_the_chinese_balancing_plot_and_accuracy_report_set_full_width_punctuation_beside_chinese_words():
    """The cycle's balancing-moment plot labelled its axes «曲柄自第一位置转过的角度, °» and «平衡力矩, N·m»; the
    accuracy report said «基准解 (mpmath) 比较»."""
    from types import SimpleNamespace

    import matplotlib

    from graphplan.report import accuracy as accuracy_report
    from graphplan.report.figures import _balancing_figure
    from graphplan.report.plot_style import settings

    scene = load(FIXTURES / "engine_slider_crank.toml")
    with matplotlib.rc_context(settings()):  # as balancing_diagram draws it, in the fonts that set Chinese
        plot = _balancing_figure(analyse(dataclasses.replace(scene, locale="zh"))).axes[0]
        russian = _balancing_figure(analyse(dataclasses.replace(scene, locale="ru"))).axes[0]
    assert plot.get_xlabel() == "曲柄自第一位置转过的角度，°" and plot.get_ylabel() == "平衡力矩，N·m"
    assert russian.get_ylabel() == "уравновешивающий момент, Н·м"
    study = SimpleNamespace(case=SimpleNamespace(compared=(1, 2, 3), left_out={}), rows=(), orders={})
    report = accuracy_report.markdown(study, "zh", "曲柄滑块机构")
    assert "基准解（mpmath）比较" in report
    assert not re.search(rf"[{CJK}][,;] |[{CJK}] ?\(|\) ?[{CJK}]", report)


def test_the_chinese_machine_note_says_starting_one_way(tmp_path):
    """The motor's «起动转矩» and «起动时» stood beside «机器启动用时» in one paragraph: 起动, as GB/T 2900 names a
    motor's start, throughout."""
    note = machine_note(tmp_path, KLOSS, "zh")[0]
    assert "起动转矩" in note and "机器起动用时" in note
    assert "启动" not in note
