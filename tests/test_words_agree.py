"""What the run writes calls one thing by one name and says only what is there: the link whose strokes are counted
(``positions.working``) is the output link in every warning, refusal and note caution, as the note's strokes
paragraph names it; errors.md tells of hand-drawn force polygons only where ``[measured.N] forces`` gives readings
of them; a [dynamics] start too fast to integrate is refused at its full key path."""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from test_fresh_user_scenes import WHITWORTH
from test_loads_of_their_own_stroke import twin
from test_output_link_turning_round import LOAD, scene_text
from test_rpm_slip_everywhere import _flywheel, _rpm_words
from test_stroke_choice import SLOTTED_BY_A_SLIDER

from graphplan.cli import main
from graphplan.locale import strings

FIXTURES = Path(__file__).resolve().parent.parent / "fixtures"
# The note's strokes paragraph's name for positions.working's link, in each language, and the other name it had.
OUTPUT_LINK = {"en": "output link", "ru": "выходное звено", "zh": "输出构件"}
OTHER_NAME = {"en": "working link", "ru": "рабочее звено", "zh": "工作构件"}


def _refusal(tmp_path: Path, capsys, text: str, command: str = "run") -> str:
    """The one error line ``command`` refuses ``text`` with, no traceback and no folder left behind."""
    scene = tmp_path / "scene.toml"
    scene.write_text(text, encoding="utf-8")
    out = tmp_path / "out"
    argv = ["run", str(scene), "--out", str(out)] if command == "run" else ["check", str(scene)]
    assert main(argv) == 2
    err = capsys.readouterr().err
    lines = [line for line in err.splitlines() if line.startswith("graphplan: error: ")]
    assert len(lines) == 1 and "Traceback" not in err, err
    assert not out.exists()
    return lines[0]


def _run(tmp_path: Path, capsys, text: str, only: str, locale: str = "en") -> tuple[str, Path]:
    """The console's output of a run of ``text`` and the folder it wrote."""
    tmp_path.mkdir(parents=True, exist_ok=True)
    scene = tmp_path / f"scene-{locale}.toml"
    scene.write_text(text, encoding="utf-8")
    out = tmp_path / f"out-{locale}"
    assert main(["run", str(scene), "--out", str(out), "--only", only, "--locale", locale]) == 0
    return capsys.readouterr().out, out


def _lower(text: str) -> str:
    return text.lower()


@pytest.mark.parametrize(("start", "extra", "said"), [
    ('"extreme"', "", '"extreme" needs the extreme positions of the output link, but link 3 turns round'),
    ("0.0", LOAD + 'during = "working"\n', "needs the strokes of the output link, but link 3 turns round"),
    ("0.0", '\n[[loads]]\nkind = "moment"\nlink = 3\nresisting = true\ndiagram = [[0.0, 5.0], [1.0, 10.0]]\n',
     "needs the strokes of the output link, but link 3 turns round"),
])
def test_what_needs_the_strokes_of_a_link_turning_round_names_it_the_output_link(tmp_path, capsys, start, extra,
                                                                                 said):
    told = _refusal(tmp_path, capsys, scene_text(start=start, extra=extra))
    assert said in told and "working link" not in told, told


def test_a_dwelling_output_link_is_refused_as_the_output_link(tmp_path, capsys):
    told = _refusal(tmp_path, capsys, WHITWORTH.replace("length = 0.5", "length = 0.15"))
    assert "an output link that dwells has no one extreme position" in told and "working link" not in told, told


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
@pytest.mark.parametrize(("sense", "during", "code"), [("cw", "working", "idle_throughout"),
                                                       ("ccw", "idle", "working_throughout")])
def test_the_note_cautions_on_the_strokes_name_the_output_link(tmp_path, capsys, locale, sense, during, code):
    """A slider's travel that turns link 4 ccw throughout: with working sense cw nothing is the working stroke, with
    a load of the idle stroke nothing is idle; the note's caution names link 4 as its strokes paragraph does."""
    text = SLOTTED_BY_A_SLIDER.replace("SENSE", sense).replace('during = "working"', f'during = "{during}"')
    _, out = _run(tmp_path, capsys, text, "note", locale)
    note = (out / "note.md").read_text(encoding="utf-8")
    caution = next(line for line in note.split("\n") if "4" in line and ("stroke" in line or "ход" in line
                                                                        or "行程" in line) and (
        "Caution" in line or "Внимание" in line or "注意" in line))
    assert f"{OUTPUT_LINK[locale]} 4" in _lower(caution), caution
    assert OTHER_NAME[locale] not in _lower(note), code


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_a_second_piston_s_load_is_told_against_the_output_link_on_the_console_and_in_the_note(tmp_path, capsys,
                                                                                                locale):
    told, out = _run(tmp_path, capsys, twin(180.0, 0.0, ""), "note", locale)
    warning = next(line for line in told.splitlines() if "loads[1] acts on link 6" in line)
    assert "a slider other than the output link 4" in warning and "working link" not in told, warning
    note = (out / "note.md").read_text(encoding="utf-8")
    # Russian declines the name: "не к выходному звену 4".
    named = {"en": "other than the output link 4", "ru": "не к выходному звену 4", "zh": "作用在输出构件 4 以外"}
    assert named[locale] in note, note
    assert OTHER_NAME[locale] not in _lower(note) and "рабочему звену" not in note


FRICTION = '\n[[friction]]\njoint = "O"\nf = 0.1\nradius = 0.02\n'


def _forces_paragraph(errors_md: str) -> str:
    return next(paragraph for paragraph in errors_md.split("\n\n") if "forces_N.svg" in paragraph)


def test_errors_md_tells_of_hand_drawn_polygons_only_where_the_scene_measured_them(tmp_path, capsys):
    """The ratchet gives hand readings of its plans, none of its force polygons: with friction, errors.md said
    "the reactions measured on the hand-drawn polygons ([measured] forces) are checked against them"."""
    original = (FIXTURES / "ratchet_crank_rocker.toml").read_text(encoding="utf-8")
    assert "forces" not in original.split("[measured", 1)[1]
    _, out = _run(tmp_path, capsys, original + FRICTION, "errors")
    unmeasured = _forces_paragraph((out / "errors.md").read_text(encoding="utf-8"))
    assert "hand-drawn" not in unmeasured and "[measured] forces" not in unmeasured, unmeasured
    assert "forces_friction_N.svg" in unmeasured and "not checked" not in unmeasured, unmeasured
    measured = original.replace("[measured.5]\n", "[measured.5]\nforces = { R23 = 50.0 }\n") + FRICTION
    _, out = _run(tmp_path / "measured", capsys, measured, "errors")
    told = _forces_paragraph((out / "errors.md").read_text(encoding="utf-8"))
    assert "measured on the hand-drawn polygons ([measured] forces) are checked against them" in told


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_errors_md_says_the_friction_polygons_are_checked_where_forces_md_checks_them(tmp_path, capsys, locale):
    """errors.md said the polygons with friction "are not checked", where the note says they are checked in the
    force analysis against the linear system with friction: it now says so too, and forces.md does hold that check."""
    original = (FIXTURES / "ratchet_crank_rocker.toml").read_text(encoding="utf-8")
    _, out = _run(tmp_path, capsys, original + FRICTION, "errors,forces", locale)
    told = _forces_paragraph((out / "errors.md").read_text(encoding="utf-8"))
    text = strings(locale)
    # The sentence each language said they were not checked with, and the note's own words for where they are.
    unchecked = {"en": "not checked", "ru": "не проверяются", "zh": "不作校核"}[locale]
    checked = {"en": "are checked in the force analysis (forces.md), against the linear system with friction",
               "ru": "проверяются в силовом расчёте (forces.md) — по системе уравнений равновесия с трением",
               "zh": "在力分析（forces.md）中与计入摩擦的平衡方程组比较"}[locale]
    assert unchecked not in told and checked in told, told
    # The check errors.md points to: the reactions of the polygons with friction against the system with friction.
    assert text["forces_friction_reactions"] in (out / "forces.md").read_text(encoding="utf-8")


def test_a_start_too_fast_is_refused_at_its_full_key_path(tmp_path, capsys):
    told = _refusal(tmp_path, capsys, _flywheel("start = { omega = 1450 }\n"), command="check")
    assert told.startswith("graphplan: error: dynamics.start.omega: 1450 rad/s is "), told
    assert _rpm_words("dynamics.start.omega", 1450.0) in told


def test_a_start_too_fast_given_in_rpm_is_refused_at_the_rpm_key(tmp_path, capsys):
    # 100 times the press's 100 rpm, within the speeds a shaft turns at and the start speeds read as a machine's, but
    # more turns than a run integrates to slow down from.
    told = _refusal(tmp_path, capsys, _flywheel("start = { rpm = 1e4 }\n"), command="check")
    # Told as typed, in rev/min, with the rad/s it is: the rpm question does not arise.
    assert told.startswith(f"graphplan: error: dynamics.start.rpm: 1e+04 rpm ({1e4 * math.pi / 30:.4g} rad/s) is "), \
        told
    assert "typed for rad/s" not in told


def test_a_start_s_driving_half_too_fast_is_refused_at_its_own_key(tmp_path, capsys):
    extra = 'clutch = { torque = 500, engage_at = 0.1 }\nstart = { omega = 10, driving_omega = 1440 }\n'
    told = _refusal(tmp_path, capsys, _flywheel(extra), command="check")
    assert told.startswith("graphplan: error: dynamics.start.driving_omega: 1440 rad/s is "), told
    assert _rpm_words("dynamics.start.driving_omega", 1440.0) in told
