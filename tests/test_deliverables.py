"""What a run delivers: every piece the scene has data for by default, only those asked for, nothing it
cannot give; the command line's options; the starter scenes of ``graphplan new``."""

from __future__ import annotations

import contextlib
import functools
import io
import json
import math
import re
import tomllib
from pathlib import Path
from xml.etree import ElementTree

import pytest
from scene_texts import crank_rocker_working_its_quicker_stroke
from sheet_texts import flat
from test_note_lever_on_course_sheet import sentence_pattern
from test_scene_errors import to_toml

import graphplan
from graphplan.cli import Progress, main
from graphplan.output import WRITTEN
from graphplan.starters import KINDS, MECHANISMS, starter

ROOT = Path(__file__).resolve().parent.parent
RATCHET = ROOT / "fixtures" / "ratchet_crank_rocker.toml"
NS = {"svg": "http://www.w3.org/2000/svg"}


def run(tmp_path: Path, *options: str, scene: Path = RATCHET) -> tuple[int, Path]:
    out = tmp_path / "out"
    return main(["run", str(scene), "--out", str(out), *options]), out


def names(folder: Path) -> set[str]:
    """The files a run wrote in ``folder``, without its list of them."""
    return {path.name for path in folder.iterdir()} - {WRITTEN}


def layer_ids(svg: Path) -> set[str]:
    return {element.get("id") for element in ElementTree.parse(svg).getroot().iter() if element.get("id")}


def without_masses_and_loads(tmp_path: Path) -> Path:
    """The ratchet with its [links.N] tables and [[loads]] cut out: nothing for a force analysis."""
    document = tomllib.loads(RATCHET.read_text(encoding="utf-8"))
    del document["links"], document["loads"]
    path = tmp_path / "bare.toml"
    path.write_text(to_toml(document), encoding="utf-8")
    return path


@pytest.fixture(scope="module")
def plain_ratchet(tmp_path_factory) -> Path:
    """The ratchet run as it is, with no option: the folder of the run that three tests read (each read it of a
    run of its own, the same run three times)."""
    status, out = run(tmp_path_factory.mktemp("plain"))
    assert status == 0
    return out


def test_by_default_every_piece_the_scene_has_data_for(plain_ratchet):
    out = plain_ratchet
    assert {"results.json", "positions.svg", "diagrams.svg", "plan_5.svg", "plan_11.svg", "forces_5.svg",
            "forces_11.svg", "errors.md", "errors.csv", "forces.md", "note.md", "note.html"} <= names(out)
    # Nothing the scene has no data for: it balances no rotor and has no springs.
    assert not {name for name in names(out) if name.startswith(("rotor", "vibration"))}
    # No figure without asking: matplotlib is not worth its second by default.
    assert "balancing.svg" not in names(out)


def test_the_diagrams_of_a_slider_s_run_come_by_default_and_need_three_intervals(tmp_path, capsys):
    slider = ROOT / "fixtures" / "slider_driven.toml"
    status, out = run(tmp_path, "--only", "diagrams", scene=slider)
    assert status == 0
    svg = flat((out / "diagrams.svg").read_text(encoding="utf-8"))
    assert "ψ4(t)" in svg and "T = |Δs|/|v| = 0.2 m / 0.08 m/s = 2.5 s" in svg
    short = tmp_path / "short.toml"
    short.write_text(re.sub(r"(?m)^count\s*=.*$", "count = 3", slider.read_text(encoding="utf-8"))
                     .replace("plans       = [3, 9]", "plans = [3]"), encoding="utf-8")
    status, again = run(tmp_path / "short", "--only", "diagrams", scene=short)
    assert status == 2 and not again.exists()
    assert "'diagrams' needs at least 3 intervals between positions" in capsys.readouterr().err


def test_no_force_pieces_without_masses_or_loads(tmp_path, capsys):
    scene = without_masses_and_loads(tmp_path)
    status, out = run(tmp_path, scene=scene)
    assert status == 0
    assert not {name for name in names(out) if name.startswith("forces")}
    assert {"plan_5.svg", "errors.md"} <= names(out)
    status, again = run(tmp_path / "asked", "--only", "positions,forces", scene=scene)
    assert status == 2 and not again.exists()
    assert "--only[1]: 'forces' needs masses or loads" in capsys.readouterr().err


def test_friction_without_masses_or_loads_is_told_it_acts_on_nothing(tmp_path, capsys):
    """A scene's [[friction]] with no masses or loads was dropped without a word: check now says why."""
    scene = without_masses_and_loads(tmp_path)
    scene.write_text(scene.read_text(encoding="utf-8") + '\n[[friction]]\njoint = "A"\nf = 0.1\nradius = 0.01\n',
                     encoding="utf-8")
    assert main(["check", str(scene)]) == 0
    left_out = next(line for line in capsys.readouterr().out.splitlines() if line.startswith("left out: "))
    assert ("forces (needs masses or loads: the scene has neither ([links.N] mass, [[loads]]); its [[friction]] "
            "has no reactions to act through)") in left_out


def test_only_the_velocity_plans_when_only_they_are_asked_for(tmp_path):
    status, out = run(tmp_path, "--only", "velocity")
    assert status == 0
    assert names(out) == {"results.json", "plan_5.svg", "plan_11.svg"}
    ids = layer_ids(out / "plan_5.svg")
    assert any(i.startswith("velocity") for i in ids)
    assert not any(i.startswith("acceleration") for i in ids)


def test_a_force_sheet_without_the_lever_when_the_lever_is_not_asked_for(tmp_path):
    status, out = run(tmp_path, "--only", "forces")
    assert status == 0
    assert {"forces_5.svg", "forces.md"} <= names(out)
    assert not any(i.startswith("lever") for i in layer_ids(out / "forces_5.svg"))
    status, out = run(tmp_path / "with", "--only", "forces,lever")
    assert any(i.startswith("lever") for i in layer_ids(out / "forces_5.svg"))


def test_the_scene_include_selects_the_pieces_and_only_overrides_it(tmp_path):
    scene = tmp_path / "included.toml"
    scene.write_text(RATCHET.read_text(encoding="utf-8") + '\n[output]\ninclude = ["positions", "errors"]\n',
                     encoding="utf-8")
    status, out = run(tmp_path, scene=scene)
    assert status == 0
    assert names(out) == {"results.json", "positions.svg", "errors.md", "errors.csv", "errors.tex"}
    status, out = run(tmp_path / "only", "--only", "positions", scene=scene)
    assert names(out) == {"results.json", "positions.svg"}


def test_unknown_pieces_and_formats_are_refused_with_their_place(tmp_path, capsys):
    status, out = run(tmp_path, "--only", "velocity,plans")
    assert status == 2 and not out.exists()
    assert "--only[1]: must be one of positions, velocity" in capsys.readouterr().err
    status, out = run(tmp_path, "--format", "svg,jpg")
    assert status == 2 and not out.exists()
    assert "--format[1]: must be one of svg, png, pdf, dxf, docx; did you mean 'png'? (got 'jpg')" in \
        capsys.readouterr().err


def test_a_misspelt_piece_or_format_names_what_was_meant(tmp_path, capsys):
    """As a misspelt value in the scene does (its [output] include among them)."""
    status, out = run(tmp_path, "--only", "velocit")
    assert status == 2 and not out.exists()
    assert "; did you mean 'velocity'? (got 'velocit')" in capsys.readouterr().err
    status, out = run(tmp_path, "--format", "svg,pnng")
    assert status == 2 and not out.exists()
    assert "--format[1]: must be one of svg, png, pdf, dxf, docx; did you mean 'png'? (got 'pnng')" in \
        capsys.readouterr().err


def test_the_locale_option_turns_the_drawings_language(tmp_path):
    status, out = run(tmp_path, "--only", "velocity", "--locale", "zh")
    assert status == 0
    texts = " ".join(element.text or "" for element in ElementTree.parse(out / "plan_5.svg").getroot().iter())
    assert re.search(r"[\u4e00-\u9fff]", texts)


@pytest.fixture(scope="module")
def new_checked_and_run(tmp_path_factory):
    """``graphplan new KIND`` written as the starter, checked, and run: what check printed and the run's folder,
    made once a kind for the module (the shaper's whole run is read by two tests)."""

    @functools.cache
    def made(kind: str) -> tuple[str, Path]:
        folder = tmp_path_factory.mktemp(kind)
        scene = folder / f"{kind}.toml"
        assert main(["new", kind, "--out", str(scene)]) == 0
        assert scene.read_text(encoding="utf-8") == starter(kind)
        printed = io.StringIO()
        with contextlib.redirect_stdout(printed):
            assert main(["check", str(scene)]) == 0
        status, out = run(folder, scene=scene)
        assert status == 0
        return printed.getvalue(), out

    return made


@pytest.mark.parametrize("kind", MECHANISMS)
def test_each_starter_scene_checks_and_runs(kind, new_checked_and_run):
    checked, out = new_checked_and_run(kind)
    assert "structure:" in checked
    assert {"results.json", "positions.svg", "errors.md"} <= names(out)
    assert any(name.startswith("forces_") for name in names(out))


@pytest.mark.parametrize(("kind", "drawings"), [
    ("flywheel", {"dynamics.svg", "motion.svg"}),
    ("rotor", {"rotor_balancing.svg", "vibration_magnification.svg", "vibration_transmissibility.svg"}),
])
def test_each_machine_starter_runs_without_a_linkage_and_explains_itself(kind, drawings, new_checked_and_run):
    checked, out = new_checked_and_run(kind)
    assert "no mechanism; " in checked
    assert names(out) == {"results.json", "note.md", "note.html", "note.tex"} | drawings
    note = (out / "note.md").read_text(encoding="utf-8")
    if kind == "flywheel":
        # The punching press of the published example: ΔWmax = 441.24 J, JF = 80.473 kg·m², 0.388 kg·m² at 1440 rpm.
        assert "ΔWmax = 441.24 J" in note and "JF = 80.473 kg·m²" in note and "= 0.38808 kg·m²" in note
    else:
        assert "Check: with the corrections Σ m·r = 0 kg·m and Σ m·r·z = 0 kg·m²" in note


def test_the_sheets_alone_hold_the_dynamics_too(tmp_path):
    """--only sheets drew the kinematics and force sheets unasked but left the dynamics sheet out: the set of
    sheets was the whole run's less its last."""
    scene = tmp_path / "ratchet.toml"
    scene.write_text(RATCHET.read_text(encoding="utf-8") + "\n[dynamics]\ndelta = 0.05\n", encoding="utf-8")
    status, out = run(tmp_path, "--only", "sheets", scene=scene)
    assert status == 0 and "dynamics.svg" not in names(out)
    sheets = sorted(out.glob("sheet_*.svg"), key=lambda path: int(path.stem.removeprefix("sheet_")))
    assert "dynamics-energy-mass" in set().union(*(layer_ids(sheet) for sheet in sheets))


def test_the_shaper_starter_runs_the_whole_course(new_checked_and_run):
    """Plans, forces with friction, the flywheel and the equation of motion, whose steady turn keeps the 60 rpm the
    scene's crank is given (the gear ratio is chosen for it) and stays within the flywheel's δ."""
    _, out = new_checked_and_run("shaper")   # the starter as written, run with no option
    assert {"forces_friction_3.svg", "dynamics.svg", "motion.svg", "sheet_1.svg"} <= names(out)
    # The course's last sheet is the dynamics of the machine, as the course project's is.
    sheets = sorted(out.glob("sheet_*.svg"), key=lambda path: int(path.stem.removeprefix("sheet_")))
    dynamics = [path.name for path in sheets if "Dynamics of the machine" in path.read_text(encoding="utf-8")]
    assert dynamics == [sheets[-1].name]
    assert {"dynamics-energy-mass", "dynamics-inertia"} <= layer_ids(sheets[-1])
    results = json.loads((out / "results.json").read_text(encoding="utf-8"))
    steady = results["dynamics"]["motion"]
    assert steady["omega_mean"] == pytest.approx(2 * math.pi, rel=0.02)
    assert 0 < steady["delta"] <= results["dynamics"]["delta"]
    efficiencies = [position["forces"]["friction"]["efficiency"] for position in results["positions"]
                    if position.get("forces")]
    assert len(efficiencies) == 2 and all(0 < eta < 1 for eta in efficiencies)


def test_the_dynamics_alone_are_drawn_without_choosing_the_length_scale(new_checked_and_run, tmp_path, monkeypatch):
    """--only dynamics chose μl, laying every sheet of the shaper out at a few μl, for drawings that have scales of
    their own: the run took 9 s where its dynamics take 2.  The drawings are the whole run's, byte for byte."""
    from graphplan.render import sheet

    _, whole = new_checked_and_run("shaper")

    def refused(*_):
        raise AssertionError("μl chosen for a run that draws nothing at μl")

    monkeypatch.setattr(sheet, "fewest_sheets_length_scale", refused)
    status, out = run(tmp_path, "--only", "dynamics", scene=whole.parent / "shaper.toml")
    assert status == 0
    assert {name for name in names(out) if name.endswith(".svg")} == {"dynamics.svg", "motion.svg"}
    assert all((out / name).read_bytes() == (whole / name).read_bytes() for name in ("dynamics.svg", "motion.svg"))


def test_a_machine_that_stalls_is_told_on_the_command_line_in_the_results_and_in_the_note(tmp_path, capsys):
    """The shaper starter with half its motor: the crank cannot pass the cutting stroke's peak from rest."""
    scene = tmp_path / "shaper.toml"
    weaker = starter("shaper").replace("power = 3000.0", "power = 1500.0")
    assert weaker != starter("shaper")
    scene.write_text(weaker, encoding="utf-8")
    status, out = run(tmp_path, "--only", "dynamics,note", scene=scene)
    assert status == 0
    motion = json.loads((out / "results.json").read_text(encoding="utf-8"))["dynamics"]["motion"]
    assert "omega_mean" not in motion
    assert motion["stalled_at"] == motion["duration"]
    assert 0 <= motion["stalled_at_angle_deg"] < 360
    # As the driver's angle_deg reads: the crank's own angle, not the angle turned from position 1 (the run's).
    document = json.loads((out / "results.json").read_text(encoding="utf-8"))
    first, sense = document["positions"][0]["driver"]["angle_deg"], -1.0  # the starter's crank turns clockwise
    assert document["positions"][0]["driver"]["omega"] < 0
    printed = capsys.readouterr().out
    turned = float(re.search(r"\(([\d.]+)° from position 1\)", printed).group(1))
    assert (first + sense * turned - motion["stalled_at_angle_deg"]) % 360 == pytest.approx(0.0, abs=0.06) or \
        (first + sense * turned - motion["stalled_at_angle_deg"]) % 360 == pytest.approx(360.0, abs=0.06)
    assert (f"warning: dynamics: the machine stalls at t = {motion['stalled_at']:.4g} s, "
            f"φ = {motion['stalled_at_angle_deg']:.4g}° ({turned:.4g}° from position 1)") in printed
    assert "it stalls, coming to rest" in (out / "note.md").read_text(encoding="utf-8")
    # check warns of it as run does (it said ok and nothing more, a teacher's variant).
    assert main(["check", str(scene)]) == 0
    checked = capsys.readouterr().out
    stall = next(line for line in printed.splitlines() if line.startswith("warning: dynamics: the machine stalls"))
    assert stall in checked.splitlines()
    # motion.svg shows why: the motor's torque against the resistance over the angle turned.
    figure = (out / "motion.svg").read_text(encoding="utf-8")
    assert "Why it stalls" in figure and "the resisting forces reduced to the shaft" in figure


def test_a_run_that_ends_short_of_a_steady_state_is_told_so_and_flagged(tmp_path, capsys):
    """The flywheel starter with a machine of 10⁶ kg·m²: after its 2000 turns' time the run ended still speeding
    up with no word on the command line and nothing in results.json but the missing ωm (a teacher's variant)."""
    scene = tmp_path / "heavy.toml"
    heavy = starter("flywheel").replace("inertia = 0.0 ", "inertia = 1e6 ", 1)
    assert heavy != starter("flywheel")
    scene.write_text(heavy, encoding="utf-8")
    status, out = run(tmp_path, "--only", "dynamics,note", scene=scene)
    assert status == 0
    motion = json.loads((out / "results.json").read_text(encoding="utf-8"))["dynamics"]["motion"]
    assert motion["steady"] is False and "omega_mean" not in motion and "stalled_at" not in motion
    printed = capsys.readouterr().out
    told = re.search(r"warning: dynamics: no steady state within the run, t = ([\d.]+) s .*still speeding up at "
                     r"ω = ([\d.]+) rad/s", printed)
    assert told and float(told[1]) == pytest.approx(motion["duration"], rel=1e-3)
    assert "No steady state was reached within the run" in (out / "note.md").read_text(encoding="utf-8")
    # The starter as it is settles: flagged steady, and no such warning.
    scene.write_text(starter("flywheel"), encoding="utf-8")
    status, out = run(tmp_path, "--only", "dynamics", scene=scene)
    assert status == 0 and "no steady state" not in capsys.readouterr().out
    assert json.loads((out / "results.json").read_text(encoding="utf-8"))["dynamics"]["motion"]["steady"] is True


@pytest.mark.parametrize("duration", [3.3, 3.9])
def test_a_run_that_ends_short_of_a_steady_state_inside_a_turn_is_told_its_trend_over_whole_turns(duration):
    """The flywheel starter run for a few seconds gains speed turn by turn (the turns' mean speeds 2.99, 7.23,
    10.4 rad/s), but within a turn it slows while the press punches: a run that ends there was told the machine
    was still slowing down."""
    scene = tomllib.loads(starter("flywheel"))
    scene["dynamics"]["duration"] = duration
    dynamics = graphplan.load(scene).machine_dynamics()
    motion = dynamics.motion
    assert motion.steady is None and len(motion.cycles) >= 2
    assert motion.cycles[-1].mean_speed > motion.cycles[-2].mean_speed
    warning = dynamics.unsettled_warning()
    assert "still speeding up" in warning and "slowing" not in warning


def test_a_machine_that_speeds_up_without_end_is_told_so_not_to_run_longer(tmp_path):
    """A constant motor above the press's mean resistance (18·14.4 = 259.2 N·m against 245.79) run for 5 s: the
    machine gains 84 J a turn and never settles, but it was told it was still slowing down and that a longer
    duration would run it on."""
    text = re.sub(r"^motor = .*$", 'motor = { kind = "constant", torque = 18.0, gear_ratio = 14.4 }\nduration = 5.0',
                  starter("flywheel"), count=1, flags=re.MULTILINE)
    assert "duration = 5.0" in text
    scene = tmp_path / "runaway.toml"
    scene.write_text(text, encoding="utf-8")
    dynamics = graphplan.load(tomllib.loads(text)).machine_dynamics()
    warning = dynamics.unsettled_warning()
    assert "speeds up without end" in warning and "259.2 N·m" in warning and "245.79 N·m" in warning
    assert "slowing" not in warning and "longer" not in warning
    status, out = run(tmp_path, "--only", "dynamics,note", scene=scene)
    assert status == 0
    assert "so it speeds up without end" in (out / "note.md").read_text(encoding="utf-8")


def test_new_does_not_overwrite_a_scene(tmp_path, capsys):
    scene = tmp_path / "mine.toml"
    scene.write_text("# my own work\n", encoding="utf-8")
    assert main(["new", "crank-rocker", "--out", str(scene)]) == 2
    assert scene.read_text(encoding="utf-8") == "# my own work\n"
    assert "exists already" in capsys.readouterr().err


@pytest.mark.parametrize("kind", ["shaper", "rotor"])
@pytest.mark.parametrize("locale", ["ru", "zh"])
def test_new_writes_a_starter_in_the_language_asked_for(tmp_path, kind, locale):
    """graphplan new wrote every starter with locale = "en": a Chinese student's first run drew English sheets."""
    import graphplan

    scene = tmp_path / f"{kind}.toml"
    assert main(["new", kind, "--locale", locale, "--out", str(scene)]) == 0
    written = scene.read_text(encoding="utf-8")
    assert graphplan.load(scene).locale == locale
    # Its comments stay the English starter's, and so do its numbers: only the words it prints are translated,
    # and the names of the [project] table it offers to fill in.
    english = starter(kind)
    assert comments(written) == comments(english)
    assert numbers(written) == numbers(english)


def comments(text: str) -> list[str]:
    offered = re.compile(r"^# (author|checked_by|organization|designation)\s*=")
    return [line.partition("#")[2] for line in text.splitlines() if not offered.match(line)]


def numbers(text: str) -> list[str]:
    return re.findall(r"[-+]?\d+(?:\.\d+)?(?:e[-+]?\d+)?", "\n".join(line.partition("#")[0] for line in text.splitlines()))


# A word of two or more Latin letters: a point's or a link's designation (O, S2, A1) is not one.
LATIN_WORD = re.compile(r"[A-Za-z]{2,}")


@pytest.mark.parametrize("kind", KINDS)
def test_the_english_starter_is_its_template(kind):
    from importlib import resources

    assert starter(kind) == resources.files("graphplan").joinpath("templates", f"{kind}.toml").read_text("utf-8")


@functools.cache
def starter_note(kind: str, locale: str):
    """The starter of ``kind`` in ``locale`` as loaded, and its note."""
    from graphplan.analysis import analyse
    from graphplan.report.note import note_markdown

    scene = graphplan.load_text(starter(kind, locale))
    return scene, note_markdown(analyse(scene) if scene.has_linkage else None, scene=scene)


def starter_heading(kind: str, locale: str):
    """The starter of ``kind`` in ``locale`` as loaded, and its note's heading, written without the linkage's
    sections: the note writes its heading first, from the scene's title alone, before any section, so it is the
    whole note's first line (checked the same for every starter in ru and zh).  The linkage's sections choose μl
    by laying out every sheet, 15-45 s of a starter with a linkage here, for a line that does not read it."""
    from graphplan.report.note import note_markdown

    scene = graphplan.load_text(starter(kind, locale))
    return scene, note_markdown(None, scene=scene).splitlines()[0]


@pytest.mark.parametrize("kind", KINDS)
@pytest.mark.parametrize("locale", ["ru", "zh"])
def test_a_starter_in_another_language_prints_no_english_words(kind, locale):
    """graphplan new shaper --locale ru titled its note «Пояснительная записка: Shaping machine» and named the
    ram's guide «∥ ram» in its plans, and the title block of every sheet read "Shaping machine"."""
    scene, heading = starter_heading(kind, locale)
    assert scene.locale == locale
    assert not LATIN_WORD.search(scene.title), scene.title
    assert not any(LATIN_WORD.search(name) for name in scene.frame_lines), list(scene.frame_lines)
    assert heading.startswith("# ") and scene.title in heading and not LATIN_WORD.search(heading), heading


@pytest.mark.parametrize("locale", ["ru", "zh"])
def test_the_shapers_guide_is_named_in_the_starters_language(locale):
    import graphplan

    scene = graphplan.load_text(starter("shaper", locale))
    (guide,) = scene.frame_lines
    assert guide != "ram" and not LATIN_WORD.search(guide)
    # The RRP group runs on it: the rename reached both the line and the group that names it.
    assert graphplan.load_text(starter("shaper")).frame_lines.keys() == {"ram"}
    assert guide in starter("shaper", locale).split("[[groups]]")[2]


@pytest.mark.parametrize("locale", ["ru", "zh"])
def test_the_title_block_of_a_starters_sheet_is_in_its_language(tmp_path, locale):
    import graphplan

    scene = tmp_path / "slider-crank.toml"
    assert main(["new", "slider-crank", "--locale", locale, "--out", str(scene)]) == 0
    status, out = run(tmp_path, "--only", "sheets", scene=scene)
    assert status == 0
    block = next(group for group in ElementTree.parse(out / "sheet_1.svg").getroot().iter(f"{{{NS['svg']}}}g")
                 if group.get("id") == "title-block")
    texts = [element.text for element in block.iter() if element.text and element.text.strip()]
    # The title may be broken over the block's lines.
    title = graphplan.load(scene).title
    assert all(word in " ".join(texts) for word in title.split()), texts
    assert not any(LATIN_WORD.search(text) for text in texts), texts


def test_a_progress_line_only_once_a_second_has_passed(capsys):
    Progress(after=3600.0).say("analysing")
    assert capsys.readouterr().err == ""
    Progress(after=-1.0).say("analysing")
    assert capsys.readouterr().err.startswith("graphplan: analysing (")


# A stage the command line tells: lower-case words, as test_hostile_scenes knows its progress lines.
STAGE = re.compile(r"[a-z ,]+")


def test_a_long_run_s_progress_line_names_the_piece_being_made(monkeypatch, tmp_path):
    """A run told "drawing and writing the tables" once it had analysed, and nothing more: with 100 000
    positions its line sat on that stale "(3.7 s)" for 13 minutes, through the plan of positions and the note.
    Each piece's stage is told as it begins: the line standing while the plan of positions, the note and the
    folder are made names them."""
    from graphplan import deliverables, output
    from graphplan.render import positions as positions_layout
    from graphplan.run import run

    told: list[str] = []
    standing: dict[str, str] = {}

    def watched(key, make):
        def made(*args, **kwargs):
            standing[key] = told[-1]
            return make(*args, **kwargs)
        return made

    monkeypatch.setattr(positions_layout, "layout", watched("positions", positions_layout.layout))
    monkeypatch.setattr(deliverables, "tables", watched("note", deliverables.tables))
    monkeypatch.setattr(output, "write_folder", watched("folder", output.write_folder))
    run(graphplan.load(RATCHET), tmp_path / "out", only=["positions", "note"], say=told.append)
    assert standing == {"positions": "drawing the plan of positions", "note": "writing the note and the tables",
                        "folder": "writing the folder"}
    assert all(STAGE.fullmatch(stage) for stage in told), told


def test_the_command_line_ends_every_progress_line_and_the_last_names_the_folder(monkeypatch, capsys, tmp_path):
    """Past its second, a run prints a whole line a stage on stderr, the last the folder being written; its
    output stays on stdout."""
    from graphplan import cli

    monkeypatch.setattr(cli, "Progress", lambda: Progress(after=-1.0))
    assert main(["run", str(RATCHET), "--out", str(tmp_path / "out"), "--only", "positions"]) == 0
    out, err = capsys.readouterr()
    assert err.endswith("\n")
    lines = err.splitlines()
    assert all(re.fullmatch(r"graphplan: [a-z ,]+ \(\d+\.\d s\)", line) for line in lines), err
    stages = [line.removeprefix("graphplan: ").split(" (")[0] for line in lines]
    assert "drawing the plan of positions" in stages and stages[-1] == "writing the folder", stages
    assert "wrote " in out and "graphplan:" not in out


ROTOR = """
[scene]
title = "Fan rotor on its mounts"
locale = "ru"

[balancing]
masses = [ { mass = 18.0, radius = 0.05, angle = 0.0, plane = 0.0 },
           { mass = 14.0, radius = 0.06, angle = -60.0, plane = 0.08 } ]
planes = [0.04, 0.22]
correction_radius = 0.05

[vibration]
mass = 100.0
unbalance = 0.02
stiffness = 1.0e5
damping_ratio = 0.1
rpm = 600.0
"""


def test_a_rotor_without_a_linkage_is_balanced_and_its_vibration_plotted(tmp_path):
    scene = tmp_path / "rotor.toml"
    scene.write_text(ROTOR, encoding="utf-8")
    status, out = run(tmp_path, "--format", "svg,dxf", scene=scene)
    assert status == 0
    assert names(out) == {"results.json", "rotor_balancing.svg", "rotor_balancing.dxf",
                          "vibration_magnification.svg", "vibration_transmissibility.svg",
                          "note.md", "note.html", "note.tex"}  # the note works the rotor and its mounts out
    document = json.loads((out / "results.json").read_text(encoding="utf-8"))
    assert "positions" not in document
    left, right = document["balancing"]["planes"]
    # The correction planes balance the rotor: Σ m·r over the masses and the corrections is zero.
    first = 18.0 * 0.05 + 0j
    second = 14.0 * 0.06 * complex(math.cos(math.radians(-60.0)), math.sin(math.radians(-60.0)))
    corrections = sum(plane["mass_radius"] * complex(math.cos(math.radians(plane["angle_deg"])),
                                                     math.sin(math.radians(plane["angle_deg"])))
                      for plane in (left, right))
    assert abs(first + second + corrections) < 1e-9
    # A machine at r = ω/ωn = 62.83/31.62 with ζ = 0.1: the closed form of the amplitude m·e·r²/M/√(…).
    r = (600.0 * math.pi / 30.0) / math.sqrt(1.0e5 / 100.0)
    expected = 0.02 / 100.0 * r * r / math.sqrt((1 - r * r) ** 2 + (2 * 0.1 * r) ** 2)
    assert document["vibration"]["amplitude"] == pytest.approx(expected, rel=1e-10)
    assert main(["check", str(scene)]) == 0


def test_a_linkage_table_without_the_linkage_is_refused(tmp_path, capsys):
    scene = tmp_path / "half.toml"
    scene.write_text(ROTOR + "\n[positions]\ncount = 12\n", encoding="utf-8")
    status, out = run(tmp_path, scene=scene)
    assert status == 2 and not out.exists()
    assert "positions: describes a mechanism: a scene with one needs [frame] and [driver] too" in capsys.readouterr().err


def test_a_linkage_piece_of_a_rotor_scene_is_refused(tmp_path, capsys):
    scene = tmp_path / "rotor.toml"
    scene.write_text(ROTOR, encoding="utf-8")
    status, out = run(tmp_path, "--only", "balancing,velocity", scene=scene)
    assert status == 2 and not out.exists()
    assert "--only[1]: 'velocity' needs a mechanism" in capsys.readouterr().err


def test_a_dynamics_table_brings_the_flywheel(tmp_path, plain_ratchet):
    scene = tmp_path / "with_flywheel.toml"
    scene.write_text(RATCHET.read_text(encoding="utf-8") + "\n[dynamics]\ndelta = 0.05\n", encoding="utf-8")
    status, out = run(tmp_path, scene=scene)
    assert status == 0
    assert "dynamics.svg" in names(out)
    dynamics = json.loads((out / "results.json").read_text(encoding="utf-8"))["dynamics"]
    # The crank's mean speed is the driver's 17 rad/s; δ = 0.05 bounds it at ωm·(1 ± δ/2).
    assert dynamics["omega_max"] == pytest.approx(17.0 * 1.025, rel=1e-12)
    assert dynamics["omega_min"] == pytest.approx(17.0 * 0.975, rel=1e-12)
    energy = dynamics["kinetic_energy_change"]
    assert dynamics["delta_w_max"] == pytest.approx(max(energy) - min(energy), rel=1e-9)
    assert len(dynamics["reduced_inertia"]) == len(dynamics["reduced_moment"]) == len(energy)
    # Without the table, no dynamics at all.
    assert "dynamics.svg" not in names(plain_ratchet)


def test_the_machine_run_by_its_motor_fluctuates_as_its_flywheel_was_sized(tmp_path):
    """With the flywheel sized for δ = 0.05 at 17 rad/s on the shaft, the integrated steady state
    fluctuates by δ·ωm² ≈ 0.05·17² (the flywheel estimate ΔWmax = J·ωm²·δ), whatever speed the motor settles at."""
    scene = tmp_path / "driven.toml"
    scene.write_text(RATCHET.read_text(encoding="utf-8") + "\n[dynamics]\ndelta = 0.05\n"
                     'motor = { kind = "linear", stall_torque = 2000.0, no_load_rpm = 170.0 }\n', encoding="utf-8")
    status, out = run(tmp_path, "--only", "dynamics", scene=scene)
    assert status == 0
    motion = json.loads((out / "results.json").read_text(encoding="utf-8"))["dynamics"]["motion"]
    middle = (motion["omega_max"] + motion["omega_min"]) / 2
    assert motion["delta"] * middle ** 2 == pytest.approx(0.05 * 17.0 ** 2, rel=0.05)
    assert motion["method"] in ("RK45", "DOP853", "LSODA", "Radau", "BDF") and motion["method_reason"]


def test_a_motor_for_a_slider_driven_mechanism_is_refused_by_name(tmp_path, capsys):
    """The equation of motion repeats over the crank's turns; a slider's stroke does not, so it has none."""
    scene = tmp_path / "slider_motor.toml"
    scene.write_text((ROOT / "fixtures" / "slider_driven.toml").read_text(encoding="utf-8")
                     + '\n[dynamics]\nmotor = { kind = "constant", torque = 50 }\n', encoding="utf-8")
    status, out = run(tmp_path, scene=scene)
    err = capsys.readouterr().err
    assert status == 2 and not out.exists()
    assert err.startswith("graphplan: error: dynamics.motor: is for the equation of motion, integrated over the turns "
                          "of a crank; this scene's positions run once over driver.travel")


def test_sheets_when_the_scene_names_its_sheet_each_the_size_of_its_format(tmp_path, plain_ratchet):
    status, out = run(tmp_path, "--only", "sheets")
    assert status == 0
    sheets = sorted(name for name in names(out) if name.startswith("sheet_"))
    assert sheets and all(name.endswith(".svg") for name in sheets)
    for name in sheets:
        root = ElementTree.parse(out / name).getroot()
        assert (root.get("width"), root.get("height")) == ("841mm", "594mm")  # the ratchet asks for A1
    # The ratchet names its sheet: a plain run draws the sheets too, the same as when asked for.
    plain = plain_ratchet
    assert {name for name in names(plain) if name.startswith("sheet_")} == set(sheets)
    assert all((plain / name).read_bytes() == (out / name).read_bytes() for name in sheets)
    # A scene that names no sheet gets none unless it asks.
    document = tomllib.loads(RATCHET.read_text(encoding="utf-8"))
    del document["drawing"]["sheet"]
    unnamed = tmp_path / "unnamed.toml"
    unnamed.write_text(to_toml(document), encoding="utf-8")
    status, bare = run(tmp_path / "bare", scene=unnamed)
    assert status == 0 and "plan_5.svg" in names(bare)
    assert not any(name.startswith("sheet_") for name in names(bare))
    status, asked = run(tmp_path / "asked", "--only", "sheets", scene=unnamed)
    assert status == 0 and any(name.startswith("sheet_") for name in names(asked))


def test_the_drawings_on_their_own_are_the_same_with_or_without_the_sheets(tmp_path):
    """The sheets reuse the drawings laid out for their own files: that changes none of those files."""
    status, together = run(tmp_path / "together", "--only", "positions,velocity,acceleration,forces,lever,sheets")
    assert status == 0
    status, alone = run(tmp_path / "alone", "--only", "positions,velocity,acceleration,forces,lever")
    assert status == 0
    drawn = {name for name in names(alone) if name.endswith(".svg")}
    assert drawn == {"positions.svg", "plan_5.svg", "plan_11.svg", "forces_5.svg", "forces_11.svg"}
    assert all((together / name).read_bytes() == (alone / name).read_bytes() for name in drawn)


def test_a_drawing_the_sheets_alter_to_fit_is_written_on_its_own_as_without_the_sheets(tmp_path):
    """On A3 the crank-rocker's sheets draw its lever a standard step smaller than the velocity plan and its load
    diagrams at smaller fields: forces_2.svg and load_diagrams.svg, and the note that works the lever at the μV
    forces_2.svg draws it at, stay as a run without the sheets writes them."""
    document = tomllib.loads(crank_rocker_working_its_quicker_stroke())
    document["positions"]["plans"] = [2]  # one force sheet is enough, and keeps the runs to a few seconds
    scene = tmp_path / "crank_rocker.toml"
    scene.write_text(to_toml(document), encoding="utf-8")
    status, sheets = run(tmp_path / "sheets", "--only", "forces,lever,load_diagrams,note,sheets", "--sheet", "A3",
                         scene=scene)
    assert status == 0
    status, alone = run(tmp_path / "alone", "--only", "forces,lever,load_diagrams,note", scene=scene)
    assert status == 0
    own = sorted(name for name in names(alone) if name.endswith(".svg"))
    assert "forces_2.svg" in own and "load_diagrams.svg" in own
    assert sorted(name for name in names(sheets) if name.endswith(".svg") and not name.startswith("sheet_")) == own
    assert [name for name in own if (sheets / name).read_bytes() != (alone / name).read_bytes()] == []

    def texts(path: Path, pattern: str) -> set[str]:
        return set(re.findall(pattern, flat(path.read_text(encoding="utf-8"))))

    # The lever on its own at the velocity plan's μV, |ω|·lOA over the pole's 150 mm; the sheets' a step coarser.
    driver = document["driver"]
    plan_scale = abs(driver["omega"]) * driver["length"] / document["drawing"]["velocity_pole"]
    lever = r"μV = ([0-9.]+) \(m/s\)/mm"
    assert [float(value) for value in texts(alone / "forces_2.svg", lever)] == [pytest.approx(plan_scale, rel=1e-3)]
    drawn = set().union(*(texts(sheet, lever) for sheet in sheets.glob("sheet_*.svg")))
    assert any(float(value) > 1.1 * plan_scale for value in drawn)
    # The note says the lever is drawn at another μV than the plan's only where forces_2.svg draws it so; with the
    # sheets it adds only, after the lever's table, the sheet that draws it coarser.
    assert "The lever is drawn larger" not in (alone / "note.md").read_text(encoding="utf-8")
    told = sentence_pattern("en")
    paragraphs = (sheets / "note.md").read_text(encoding="utf-8").split("\n\n")
    assert any(told.fullmatch(paragraph) for paragraph in paragraphs)
    assert "\n\n".join(paragraph for paragraph in paragraphs if not told.fullmatch(paragraph)) == \
        (alone / "note.md").read_text(encoding="utf-8")
    # The load diagrams' scales on the sheets are not those of load_diagrams.svg: their fields were made smaller.
    moments = r"μM = [0-9.]+ N·m/mm"
    assert texts(alone / "load_diagrams.svg", moments)
    assert not texts(alone / "load_diagrams.svg", moments) & set().union(
        *(texts(sheet, moments) for sheet in sheets.glob("sheet_*.svg")))


def test_a_scene_whose_plan_of_positions_fits_no_named_sheet_is_refused_with_the_scale_that_fits(tmp_path, capsys):
    document = tomllib.loads(RATCHET.read_text(encoding="utf-8"))
    document["drawing"].update(sheet="A4", length_scale=0.001)
    path = tmp_path / "tiny_sheet.toml"
    path.write_text(to_toml(document), encoding="utf-8")
    status, out = run(tmp_path, scene=path)
    assert status == 2 and not out.exists()
    error = capsys.readouterr().err
    assert "drawing.sheet" in error and "no A4 sheet" in error
    fitting = float(re.search(r"length_scale = ([0-9.]+)", error).group(1))
    # The ratchet's paths span 0.73 m; at the named scale they would be 730 mm, at the one given < 290 mm.
    assert 0.73 / fitting < 290.0


def test_the_russian_shapers_note_writes_what_follows_parallel_as_russian_grammar_has_it():
    """«∥ направляющая» read "parallel to" with a nominative noun, where Russian declines it («∥ направляющей»).
    A line's name is one word in every case, so the Russian starter names its guide as the textbooks do, x–x:
    no word after ∥ in its note is a noun or adjective left in the feminine nominative."""
    _, note = starter_note("shaper", "ru")
    after_parallel = re.findall(r"∥ (\S+)", note)
    assert after_parallel
    assert not [word for word in after_parallel if re.fullmatch(r"[а-яё]+(ая|яя)", word)], set(after_parallel)


COMPRESSOR = """[scene]
title = "Compressor"
[frame]
link = 1
points = { O = [0.0, 0.0] }
[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = 0.06
rpm = 300.0
[[groups]]
kind = "RRP"
links = [3, 4]
joints = ["A", "B"]
length = 0.24
guide = { through = "O", angle = 0.0 }
assembly = "forward"
[links.2]
mass = 5.0
centre = "O"
inertia = 0.02
[links.4]
mass = 3.0
centre = "B"
[[loads]]
kind = "force"
link = 4
point = "B"
value = 2500.0
angle = 180.0
resisting = true
during = "working"
[positions]
count = 12
start = "extreme"
working = { link = 4, sense = "forward" }
[dynamics]
delta = 0.04
motor = { kind = "kloss", power = 1500.0, overload = 2.2, synchronous_rpm = 1500.0, rated_rpm = 1420.0, gear_ratio = 4.7 }
"""


def test_the_start_s_angle_is_the_crank_s_own_as_the_results_give_it(tmp_path):
    """A motor that cannot move the compression stroke's load from rest, started at the crank's own 300° (position
    1 is at 180°): it stands where it was started, and the results say so in the same angle.  The start was counted
    from position 1, and the results gave 120°."""
    scene = tmp_path / "compressor.toml"
    scene.write_text(COMPRESSOR + "start = { omega = 0.0, angle_deg = 300.0 }\n", encoding="utf-8")
    status, out = run(tmp_path, "--only", "dynamics", scene=scene)
    assert status == 0
    document = json.loads((out / "results.json").read_text(encoding="utf-8"))
    assert document["positions"][0]["driver"]["angle_deg"] == pytest.approx(180.0)
    motion = document["dynamics"]["motion"]
    assert motion["stalled_at"] == 0.0
    assert motion["stalled_at_angle_deg"] == pytest.approx(300.0)


def test_what_a_machine_without_load_diagrams_needs_is_told_without_an_analysis():
    """Asked of a scene with no analysis to go by, what its [dynamics] table (a motor, no load diagrams) needs
    asked itself the same question again, without end, until the stack ran out."""
    from graphplan.deliverables import missing
    from graphplan.scene import loads

    text = starter("crank-rocker", "en") + '\n[dynamics]\ndelta = 0.05\n[dynamics.motor]\nkind = "constant"\n' \
        "torque = 5.0\n"
    machine = loads(text)
    assert not machine.dynamics.diagrams
    for piece in ("dynamics", "note", "sheets", "velocity"):
        # None stands for no linkage: what the linkage's pieces need, and the machine's with them.
        assert missing(machine, None, piece).startswith("needs a mechanism"), piece


@pytest.mark.parametrize(("only", "title"), [("velocity", "Velocity plan, position 5"),
                                             ("acceleration", "Acceleration plan, position 5"),
                                             ("velocity,acceleration", "Velocity and acceleration plans, position 5")])
def test_a_plan_sheet_is_titled_by_the_plans_it_holds(tmp_path, only, title):
    """Under --only velocity the plan sheet, and the note's figure of it, read "Velocity and acceleration plans,
    position 5" over a sheet with no acceleration plan."""
    scene = tmp_path / "ratchet.toml"
    scene.write_text(RATCHET.read_text(encoding="utf-8").replace('locale  = "ru"', 'locale  = "en"'), encoding="utf-8")
    code, out = run(tmp_path, "--only", f"{only},note", scene=scene)
    assert code == 0
    titles = ["".join(text.itertext()) for text in ElementTree.parse(out / "plan_5.svg").getroot().iter(
        "{http://www.w3.org/2000/svg}text")]
    assert title in titles, titles
    assert not [text for text in titles if "plan" in text.lower() and "position 5" in text and text != title]
    assert f"Figure 1. {title}" in (out / "note.md").read_text(encoding="utf-8")
