"""The note's section on the machine's dynamics: its arithmetic holds, its numbers are the run's, in the scene's language."""

from __future__ import annotations

import json
import re
from pathlib import Path
from xml.etree import ElementTree

import pytest

from graphplan.cli import main

ROOT = Path(__file__).resolve().parent.parent
RATCHET = ROOT / "fixtures" / "ratchet_crank_rocker.toml"
DYNAMICS = ('\n[dynamics]\ndelta = 0.05\nflywheel_shaft_rpm = 1440\n'
            'motor = { kind = "linear", stall_torque = 2000.0, no_load_rpm = 170.0 }\n')
NUMBER = r"(−?[\d.]+(?:e[−+]?\d+)?)"


def value(text: str) -> float:
    return float(text.replace("−", "-"))


def run(tmp_path: Path, extra: str, locale: str = "en") -> tuple[str, dict]:
    text = re.sub(r'^locale\s*=\s*"ru"', f'locale = "{locale}"', RATCHET.read_text(encoding="utf-8"), flags=re.MULTILINE)
    assert f'locale = "{locale}"' in text
    text += extra
    tmp_path.mkdir(parents=True, exist_ok=True)
    scene = tmp_path / "scene.toml"
    scene.write_text(text, encoding="utf-8")
    out = tmp_path / "out"
    pieces = "note,dynamics" if extra else "note"
    assert main(["run", str(scene), "--out", str(out), "--only", pieces]) == 0
    results = json.loads((out / "results.json").read_text(encoding="utf-8"))
    return (out / "note.md").read_text(encoding="utf-8"), results


@pytest.fixture(scope="module")
def english(tmp_path_factory):
    return run(tmp_path_factory.mktemp("note"), DYNAMICS)


def section(note: str, heading: str) -> str:
    start = note.index(heading)
    return note[start:]


def test_the_flywheel_line_does_its_own_arithmetic(english):
    note, results = english
    text = section(note, "Dynamics of the machine")
    found = re.search(rf"JF = ΔWmax/\(ωm²·δ\) − Je,mean = {NUMBER}/\({NUMBER}²·{NUMBER}\) − {NUMBER} = {NUMBER} kg·m²",
                      text)
    work, omega, delta, mean, approximate = (value(group) for group in found.groups())
    assert work / (omega ** 2 * delta) - mean == pytest.approx(approximate, rel=1e-4)
    dynamics = results["dynamics"]
    assert work == pytest.approx(dynamics["delta_w_max"], rel=1e-4)
    assert approximate == pytest.approx(dynamics["flywheel_inertia_approximate"], rel=1e-4)
    assert f"JF = {dynamics['flywheel_inertia']:.5g} kg·m²" in text
    # JF′ = JF·(n/n′)² with n the crank's 17 rad/s.
    moved = value(re.search(rf"JF′ = JF·\(n/n′\)² = {NUMBER}", text).group(1))
    assert moved == pytest.approx(dynamics["flywheel_inertia"] * (17.0 * 30 / 3.141592653589793 / 1440) ** 2, rel=1e-4)


def test_the_energy_range_and_the_steady_speeds_agree_with_themselves(english):
    note, results = english
    text = section(note, "Dynamics of the machine")
    low, high, surplus = (value(group) for group in re.search(
        rf"ranges from {NUMBER} J to {NUMBER} J: the largest surplus work ΔWmax = {NUMBER} J", text).groups())
    assert high - low == pytest.approx(surplus, rel=1e-4)
    # The ωm the formula of δ divides by is the one written just before it, not the turn's mean in time.
    high_speed, low_speed, middle, delta = (value(group) for group in re.search(
        rf"ωmax = {NUMBER} rad/s, ωmin = {NUMBER} rad/s; with the textbook's ωm = \(ωmax \+ ωmin\)/2 = {NUMBER} "
        rf"rad/s, δ = \(ωmax − ωmin\)/ωm = {NUMBER}\.", text).groups())
    assert middle == pytest.approx((high_speed + low_speed) / 2, rel=1e-4)
    assert (high_speed - low_speed) / middle == pytest.approx(delta, rel=1e-3)
    motion = results["dynamics"]["motion"]
    assert delta == pytest.approx(motion["delta"], rel=1e-3)
    assert f"by the method {motion['method']}:" in text


def test_the_plan_positions_are_tabulated_with_their_reduced_inertia(english):
    note, results = english
    text = section(note, "Dynamics of the machine")
    rows = re.findall(rf"^\| (\d+) \| {NUMBER} \| {NUMBER} \| {NUMBER} \| {NUMBER} \| {NUMBER} \| {NUMBER} \| {NUMBER} \|$",
                      text, flags=re.MULTILINE)
    plans = {plan["index"]: plan for plan in results["dynamics"]["plans"]}
    assert [int(row[0]) for row in rows] == sorted(plans)
    for row in rows:
        plan = plans[int(row[0])]
        assert value(row[2]) == pytest.approx(plan["reduced_inertia"], rel=1e-4)
        assert value(row[3]) == pytest.approx(plan["reduced_inertia_exact"], rel=1e-4)
        assert value(row[5]) == pytest.approx(plan["reduced_moment"], rel=1e-4)


def test_the_reduction_is_written_with_the_driving_link_s_own_speed(english):
    """The ratchet's crank is link 2: Je = Σ[m·(vS/ω2)² + ...], not the ω1 of the textbook's numbering."""
    note, results = english
    text = section(note, "Dynamics of the machine")
    assert results["dynamics"]["driver_link"] == 2
    assert "Je = Σ[m·(vS/ω2)² + JS·(ω/ω2)²]" in text and "Me = Σ[F·v·cos α ± M·ω]/ω2" in text and "ω1" not in text


def test_in_russian_with_a_decimal_comma_and_without_dynamics_no_section(tmp_path):
    note, _ = run(tmp_path / "ru", DYNAMICS, locale="ru")
    text = section(note, "Динамический анализ машины")
    assert re.search(r"δ = 0,05 при ωср = 17 рад/с", text)
    assert "stiff" not in text and "auto:" not in text   # the integrator's reason is in Russian too
    plain, _ = run(tmp_path / "plain", "")
    assert "Dynamics of the machine" not in plain


# A symbol of the flywheel's quantities: its letter and an index of letters, which may go on after a comma (Jп,ср,
# Je,mean); a work's index is one letter (Ad, Aс, Wd), which tells it from a word.
LETTER = "A-Za-zА-Яа-яЁё"
DYNAMICS_SYMBOL = re.compile(rf"(?<!\w)(?:(?:ΔT|ΔE|ΔW|J|ω)[{LETTER}′]+(?:,[{LETTER}]+)?|[AW][{LETTER}](?![{LETTER}]))")


def drawn_words(svg: Path) -> str:
    return "\n".join(element.text or "" for element in ElementTree.parse(svg).getroot().iter())


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_the_note_and_the_dynamics_sheet_name_the_flywheel_s_quantities_alike(tmp_path, locale):
    """The Russian sheet drew Jм, Jп, Jп,ср, ωср, ΔTнб where the note beside it wrote JF, Je, Je,ср, ωm, ΔWmax for
    the same values: a reader met two notations for one quantity."""
    note, _ = run(tmp_path, DYNAMICS, locale=locale)
    text = note[note.index("\n## 6"):] if "\n## 6" in note else note
    drawn = drawn_words(tmp_path / "out" / "dynamics.svg")
    on_sheet, in_note = set(DYNAMICS_SYMBOL.findall(drawn)), set(DYNAMICS_SYMBOL.findall(text))
    # Mertsalov's constant part of the reduced inertia is on the sheet alone, the note gives his flywheel only.
    mertsalov = {"JпI", "Jc"}
    assert on_sheet - mertsalov <= in_note, sorted(on_sheet - mertsalov - in_note)
    # The flywheel's paragraphs name nothing the sheet does not: the note's other symbols are a link's own (JS),
    # the equation of motion's (Jп′, Mд(ω)) and the reduction's (Mп).
    flywheel = [line for line in text.splitlines() if re.search(r"Δ[TE] = |\(n/n′\)²|δ = 0.*/\(", line)]
    assert len(flywheel) == 3, flywheel
    flywheel = "\n".join(flywheel)
    assert set(DYNAMICS_SYMBOL.findall(flywheel)) <= on_sheet, sorted(set(DYNAMICS_SYMBOL.findall(flywheel)) - on_sheet)


@pytest.mark.parametrize(("stall_torque", "method", "stiff"), [(2000.0, "RK45", False), (2.0e6, "LSODA", True)])
def test_the_note_gives_the_run_s_own_reason_for_its_integrator(tmp_path, stall_torque, method, stiff):
    """A gentle linear motor and one a thousand times steeper: the note says stiff exactly when the run took
    LSODA for stiffness, with the run's stiffness number."""
    note, results = run(tmp_path, DYNAMICS.replace("stall_torque = 2000.0", f"stall_torque = {stall_torque}"))
    motion = results["dynamics"]["motion"]
    assert motion["method"] == method
    assert motion["method_reason"].startswith("auto: stiff" if stiff else "auto: not stiff")
    run_number = float(re.search(r"= ([\d.e+−-]+) [>≤] 3\.0; cycle", motion["method_reason"]).group(1))
    said = re.search(rf"by the method {method}: the stiffness number .*? is {NUMBER} ([>≤]) 3, ", note)
    assert value(said.group(1)) == pytest.approx(run_number, rel=5e-3)
    assert said.group(2) == (">" if stiff else "≤")
    assert ("an implicit method is taken" in note) == stiff


@pytest.mark.parametrize("locale, words", [("en", "the friction in the pairs, which the force analysis takes in, is left out"),
                                           ("ru", "трение в кинематических парах, учтённое в силовом расчёте, в них не входит"),
                                           ("zh", "未计入力分析中考虑的运动副摩擦")])
def test_the_dynamics_of_a_scene_with_friction_says_its_moments_leave_the_friction_out(tmp_path, locale, words):
    """The shaper starter has [[friction]], but Mr, the works and the flywheel are reduced from its loads alone:
    its works over the cycle are the driver's work without friction, ∫Mb0 dφ, not with it, ∫Mb dφ."""
    import numpy as np

    from graphplan.analysis import analyse
    from graphplan.motion import solve
    from graphplan.scene import load
    from graphplan.starters import starter

    scene = tmp_path / "shaper.toml"
    scene.write_text(starter("shaper", locale), encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--only", "note,dynamics,forces"]) == 0
    note = (out / "note.md").read_text(encoding="utf-8")
    assert words in note and note.count(words) == 1
    # The cutting force, 2000 N over 0.05 to 0.95 of the ram's stroke H, does 2000·0.9·H over the cycle.
    analysis = analyse(load(scene))
    ends = solve(analysis.mechanism, np.array(analysis.positions.extremes), analysis.positions.reference)
    cutting = 2000.0 * 0.9 * abs(float(np.diff(ends.point("E").r[:, 0])[0]))
    results = json.loads((out / "results.json").read_text(encoding="utf-8"))
    dynamics, cycle = results["dynamics"], results["cycle_efficiency"]
    assert dynamics["driving_work"][-1] == pytest.approx(cutting, rel=1e-4)
    assert cycle["work_without_friction"] == pytest.approx(cutting, rel=1e-8)
    assert cycle["work_with_friction"] > cutting * 1.05 and not cycle["loads_drive"]
    frictionless = tmp_path / "frictionless.toml"
    # Each [[friction]] table of the starter runs to a blank line.
    frictionless.write_text(re.sub(r"^\[\[friction\]\].*?\n\n", "", starter("shaper", locale), flags=re.MULTILINE | re.DOTALL),
                            encoding="utf-8")
    assert main(["run", str(frictionless), "--out", str(tmp_path / "bare"), "--only", "note,dynamics"]) == 0
    assert words not in (tmp_path / "bare" / "note.md").read_text(encoding="utf-8")
