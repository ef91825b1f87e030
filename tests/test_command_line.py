"""The command line: what `graphplan run` writes, and how it fails."""

import json
import math
import signal
from pathlib import Path
from xml.etree import ElementTree

import numpy as np
import pytest
from console import without_progress

import graphplan
from graphplan.cli import main

FIXTURE = "fixtures/ratchet_crank_rocker.toml"


@pytest.fixture(scope="module")
def run_folder(tmp_path_factory):
    out = tmp_path_factory.mktemp("run") / "ratchet"
    assert main(["run", FIXTURE, "--out", str(out)]) == 0
    return out


def test_results_json_follows_the_contract(run_folder):
    document = json.loads((run_folder / "results.json").read_text(encoding="utf-8"))
    assert document["structure"] == "I(1,2) → II2(3,4)"
    assert document["scene"] == "Crank-rocker of a ratchet feed"
    assert [p["index"] for p in document["positions"]] == list(range(12))
    fifth = document["positions"][5]
    assert fifth["stroke"] == "working"
    assert fifth["driver"]["omega"] == -17.0
    # The driver angle of position 5: five 30° steps clockwise from the extended dead centre.
    assert fifth["driver"]["angle_deg"] == pytest.approx((115.0476 - 150.0) % 360, abs=1e-3)
    assert set(fifth["points"]) >= {"O", "A", "B", "C", "S2", "S3", "E", "S4"}
    assert set(fifth["links"]) == {"2", "3", "4"}
    # The same numbers as the Python interface.
    motion = graphplan.solve(graphplan.load(FIXTURE))
    assert fifth["points"]["B"]["v"] == pytest.approx(list(motion.point("B").v[5]), rel=1e-11)
    assert fifth["links"]["4"]["omega"] == pytest.approx(float(motion.link(4).omega[5]), rel=1e-11)
    assert fifth["links"]["3"]["angle_deg"] == pytest.approx(math.degrees(motion.link(3).angle[5]), rel=1e-11)


def test_positions_svg_draws_every_position_and_the_paths(run_folder):
    root = ElementTree.parse(run_folder / "positions.svg").getroot()
    ns = {"svg": "http://www.w3.org/2000/svg"}
    groups = {g.get("id"): g for g in root.findall("svg:g", ns)}
    assert {"paths", "positions", "extremes", "frame", "labels", "caption"} <= set(groups)
    numbers = {"".join(t.itertext()) for t in groups["labels"].findall("svg:text", ns)}
    assert {str(i) for i in range(12)} <= numbers
    assert {"O", "A", "B", "C", "E"} <= numbers
    # The crank pin's circle and four named points' paths, all closed (the crank turns a full cycle).
    paths = groups["paths"].findall("svg:path", ns)
    assert len(paths) == 5 and all(path.get("d").rstrip().endswith("Z") for path in paths)
    caption = " ".join("".join(t.itertext()) for t in groups["caption"].findall("svg:text", ns))
    assert "0,0025" in caption  # the ratchet's μl, written with the Russian decimal comma


def test_the_same_scene_gives_the_same_bytes(tmp_path, run_folder):
    again = tmp_path / "again"
    assert main(["run", FIXTURE, "--out", str(again)]) == 0
    names = sorted(path.name for path in run_folder.iterdir())
    assert sorted(path.name for path in again.iterdir()) == names
    for name in names:
        assert (again / name).read_bytes() == (run_folder / name).read_bytes(), name


def test_results_json_names_the_versions_it_was_made_with(run_folder):
    import platform

    import numpy
    import scipy
    import shapely
    import svgwrite

    versions = json.loads((run_folder / "results.json").read_text(encoding="utf-8"))["versions"]
    assert versions == {"python": platform.python_version(), "graphplan": graphplan.__version__,
                        "numpy": numpy.__version__, "scipy": scipy.__version__, "shapely": shapely.__version__,
                        "svgwrite": svgwrite.__version__}


def test_a_bad_scene_exits_2_with_one_line_and_writes_nothing(tmp_path, capsys):
    scene = tmp_path / "bad.toml"
    text = Path(FIXTURE).read_text(encoding="utf-8").replace("lengths  = [0.55, 0.325]", "lengths  = [0.55, -0.325]")
    scene.write_text(text, encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out)]) == 2
    error = capsys.readouterr().err
    assert error.strip() == "graphplan: error: groups[0].lengths[1]: must be > 0 (got -0.325)"
    assert not out.exists()
    assert list(tmp_path.iterdir()) == [scene]


def test_an_unreachable_position_names_the_position_and_the_group(tmp_path, capsys):
    scene = tmp_path / "short.toml"
    text = Path(FIXTURE).read_text(encoding="utf-8").replace("lengths  = [0.55, 0.325]", "lengths  = [0.35, 0.325]")
    scene.write_text(text, encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "out")]) == 2
    error = capsys.readouterr().err
    assert error.startswith("graphplan: error: B cannot be assembled at φ = ")
    assert "in group II(3,4): A–C = " in error and "> AB + BC = 0.675 m" in error
    assert not (tmp_path / "out").exists()


def test_a_failed_run_leaves_an_existing_output_untouched(tmp_path, run_folder):
    import shutil

    # The module's run of the fixture, its list of the files it wrote with it: the folder a run leaves, byte for byte.
    out = tmp_path / "kept"
    shutil.copytree(run_folder, out)
    before = (out / "results.json").read_bytes()
    bad = tmp_path / "bad.toml"
    bad.write_text("[scene]\ntitle = 3\n", encoding="utf-8")
    assert main(["run", str(bad), "--out", str(out)]) == 2
    assert (out / "results.json").read_bytes() == before


def test_the_sheet_option_draws_the_sheets_on_that_format_even_for_a_scene_that_names_none(tmp_path):
    scene = tmp_path / "unsheeted.toml"
    text = Path(FIXTURE).read_text(encoding="utf-8")
    unsheeted = "\n".join(line for line in text.splitlines() if not line.startswith("sheet "))
    assert unsheeted != text
    scene.write_text(unsheeted, encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "plain")]) == 0
    assert not list((tmp_path / "plain").glob("sheet_*.svg"))
    out = tmp_path / "a2"
    assert main(["run", str(scene), "--out", str(out), "--sheet", "A2"]) == 0
    sheets = sorted(out.glob("sheet_*.svg"))
    assert sheets
    for sheet in sheets:
        root = ElementTree.parse(sheet).getroot()
        assert (root.get("width"), root.get("height")) == ("594mm", "420mm")


@pytest.mark.parametrize(("sheet", "told"), [
    ("а1", "must be one of A1, A2, A3, A4, none; did you mean 'A1'? (got 'а1')"),  # a Cyrillic а
    ("a2", "must be one of A1, A2, A3, A4, none; did you mean 'A2'? (got 'a2')"),
    ("B5", "must be one of A1, A2, A3, A4, none (got 'B5')"),
], ids=["cyrillic-a", "small-letter", "no-such-format"])
def test_a_sheet_option_mistyped_is_told_as_drawing_sheet_is(tmp_path, capsys, sheet, told):
    """argparse's 'invalid choice' gave --sheet none of the did-you-mean drawing.sheet = "А1" gets."""
    out = tmp_path / "out"
    with pytest.raises(SystemExit) as stopped:
        main(["run", FIXTURE, "--out", str(out), "--sheet", sheet])
    assert stopped.value.code == 2
    assert capsys.readouterr().err.splitlines()[-1] == f"graphplan run: error: argument --sheet: {told}"
    assert not out.exists()


def test_a_new_scene_in_a_folder_with_a_space_is_quoted_in_the_next_command(tmp_path, capsys, monkeypatch):
    """The next command, copied into a shell, must name the scene whole."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / "вариант 7").mkdir()
    assert main(["new", "shaper", "--out", "вариант 7/строгальный.toml"]) == 0
    printed = capsys.readouterr().out.splitlines()
    assert printed[-1] == ("next: graphplan check 'вариант 7/строгальный.toml', "
                           "then graphplan run 'вариант 7/строгальный.toml'")


def test_a_sheet_option_too_small_for_the_scene_names_the_option(tmp_path, capsys):
    out = tmp_path / "out"
    # 219 × 366 mm at the scene's μl: taller than an A3 stood upright leaves clear of its title block.
    assert main(["run", "fixtures/ratchet_crank_rocker.toml", "--out", str(out), "--sheet", "A3"]) == 2
    error = capsys.readouterr().err
    assert error.startswith("graphplan: error: --sheet (in place of drawing.sheet): the plan of positions is ")
    assert "no A3 sheet holds it" in error
    assert not out.exists()


def test_check_refuses_a_reading_that_names_no_segment_of_the_plan_as_the_run_does(tmp_path, capsys):
    scene = tmp_path / "measured.toml"
    scene.write_text(Path(FIXTURE).read_text(encoding="utf-8") + "\n[measured.11]\nvelocity = { pz = 10.0 }\n",
                     encoding="utf-8")
    assert main(["check", str(scene)]) == 2
    checked = capsys.readouterr().err
    assert checked.startswith("graphplan: error: measured.11.velocity.pz: is no segment of the plan: p is one of its "
                              "letters, z is none (")
    assert main(["run", str(scene), "--out", str(tmp_path / "out")]) == 2
    assert without_progress(capsys.readouterr().err) == checked


def test_check_tells_what_run_writes_and_what_it_leaves_out_for_want_of_data(tmp_path, capsys, run_folder):
    """The ratchet without its masses and loads: check says the forces are left out and why, and the run
    writes no force sheet; with them, check lists the forces and the run writes them."""
    import tomllib

    from test_scene_errors import to_toml

    document = tomllib.loads(Path(FIXTURE).read_text(encoding="utf-8"))
    for key in ("links", "loads", "measured"):
        document.pop(key, None)
    bare = tmp_path / "bare.toml"
    bare.write_text(to_toml(document), encoding="utf-8")
    for scene, has_forces in ((FIXTURE, True), (str(bare), False)):
        assert main(["check", scene]) == 0
        lines = capsys.readouterr().out.splitlines()
        pieces = next(line for line in lines if line.startswith("run writes: ")).removeprefix("run writes: ").split(", ")
        left_out = next((line for line in lines if line.startswith("left out: ")), "")
        assert ("forces" in pieces) is has_forces
        assert ("forces (needs masses or loads" in left_out) is not has_forces
        out = tmp_path / f"out-{has_forces}"
        if scene == FIXTURE:
            out = run_folder   # the module's run of the fixture as it is, with no option
        else:
            assert main(["run", scene, "--out", str(out)]) == 0
            capsys.readouterr()
        assert bool(list(out.glob("forces_*.svg"))) is has_forces
    # A rotor without a mechanism: what it writes, without a list of every mechanism's piece it lacks.
    rotor = tmp_path / "rotor.toml"
    rotor.write_text('[scene]\ntitle = "Rotor"\n[balancing]\nmasses = [ { mass = 18.0, radius = 0.05, angle = 0.0, '
                     'plane = 0.0 } ]\ncorrection_radius = 0.05\n', encoding="utf-8")
    assert main(["check", str(rotor)]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert "run writes: note, balancing" in lines and not any(line.startswith("left out") for line in lines)


def test_check_prints_the_structure_formula(capsys):
    assert main(["check", FIXTURE]) == 0
    printed = capsys.readouterr().out
    assert "structure: I(1,2) → II2(3,4)" in printed
    assert "W = 3n − 2p5 − p4 = 3·3 − 2·4 − 0 = 1" in printed


def test_the_driver_array_interface_matches_the_scene_positions():
    scene = graphplan.load(FIXTURE)
    by_scene = graphplan.solve(scene)
    by_array = graphplan.solve(scene, driver=by_scene.driver)
    np.testing.assert_array_equal(by_scene.point("E").a, by_array.point("E").a)


def test_check_refuses_an_include_the_scene_cannot_give_before_it_says_ok(tmp_path, capsys):
    # It printed "ok", the structure and the strokes, then the error and exit 2: which was it?
    scene = tmp_path / "scene.toml"
    scene.write_text(Path(FIXTURE).read_text(encoding="utf-8") + '\n[output]\ninclude = ["balancing"]\n',
                     encoding="utf-8")
    assert main(["check", str(scene)]) == 2
    printed = capsys.readouterr()
    assert printed.out == ""
    assert "output.include[0]: 'balancing' needs a [balancing] table" in printed.err


def test_run_refuses_under_only_the_include_check_refuses(tmp_path, capsys):
    """run --only positions wrote its output from a scene check refused, the include's fault unsaid."""
    scene = tmp_path / "scene.toml"
    text = Path(FIXTURE).read_text(encoding="utf-8")
    scene.write_text(text + '\n[output]\ninclude = ["positions", "balancing"]\n', encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--only", "positions", "--out", str(out)]) == 2
    assert "output.include[1]: 'balancing' needs a [balancing] table" in capsys.readouterr().err
    assert not out.exists()
    # An include of sheets is the scene's sheet's to judge, not a --sheet none given for pieces without them.
    scene.write_text(text + '\n[output]\ninclude = ["positions", "sheets"]\n', encoding="utf-8")
    assert main(["run", str(scene), "--only", "positions", "--sheet", "none", "--out", str(out)]) == 0
    assert (out / "positions.svg").is_file() and not list(out.glob("sheet_*.svg"))


@pytest.mark.parametrize("pole, key", [
    (1000.0, "drawing.sheet"),                # the acceleration plans bigger than an A1 sheet: the sheets refuse them
    (100000.0, "drawing.acceleration_pole"),  # 150 m across: every run refuses them, sheets or none
])
def test_check_refuses_what_the_run_s_drawings_would_refuse_before_it_says_ok(tmp_path, capsys, pole, key):
    """check said "ok … run writes: …, sheets" for scenes whose run then refused the sheets (a teacher's
    variants, found generating 25 of them): now check refuses each as the run does, in the run's words."""
    text = Path(FIXTURE).read_text(encoding="utf-8")
    scene = tmp_path / "scene.toml"
    scene.write_text(text.replace("acceleration_pole = 100.0", f"acceleration_pole = {pole}"), encoding="utf-8")
    assert main(["check", str(scene)]) == 2
    checked = capsys.readouterr()
    # The scene's warnings first, as the run gives them, then the one error.
    assert checked.out == "" and checked.err.splitlines()[-1].startswith(f"graphplan: error: {key}: ")
    assert all(line.startswith("warning: ") for line in checked.err.splitlines()[:-1])
    assert main(["run", str(scene), "--out", str(tmp_path / "out")]) == 2
    assert without_progress(capsys.readouterr().err) == checked.err


def test_check_refuses_a_motor_that_would_speed_the_machine_up_without_end(tmp_path, capsys):
    from graphplan.starters import starter

    scene = tmp_path / "flywheel.toml"
    text = starter("flywheel")
    motor = next(line for line in text.splitlines() if line.startswith("motor = "))
    scene.write_text(text.replace(motor, 'motor = { kind = "constant", torque = 1.0e6 }'), encoding="utf-8")
    assert main(["check", str(scene)]) == 2
    checked = capsys.readouterr()
    assert checked.out == "" and "exceeds the mean resistance" in checked.err
    assert main(["run", str(scene), "--out", str(tmp_path / "out")]) == 2
    assert without_progress(capsys.readouterr().err) == checked.err


def test_check_works_the_machine_s_dynamics_out_once(tmp_path, capsys, monkeypatch):
    """check worked the dynamics out for its refusals and again for the warnings of their outcomes, integrating
    the machine's motion each time: the second is the first one's."""
    from graphplan import machine_dynamics
    from graphplan.starters import starter

    made = []
    original = machine_dynamics.MachineDynamics.__init__

    def counted(self, source):
        made.append(source)
        original(self, source)

    monkeypatch.setattr(machine_dynamics.MachineDynamics, "__init__", counted)
    scene = tmp_path / "flywheel.toml"
    scene.write_text(starter("flywheel"), encoding="utf-8")
    assert main(["check", str(scene)]) == 0
    assert "dynamics" in capsys.readouterr().out
    assert len(made) == 1


def test_a_run_into_a_folder_keeps_what_no_run_wrote_there_and_replaces_its_own(tmp_path):
    """--out pointed at the scene's own folder deleted the scene and a draft beside it: a run replaces the
    files runs wrote there (listed in the folder) and carries everything else over."""
    from graphplan.output import WRITTEN

    folder = tmp_path / "project"
    folder.mkdir()
    scene = folder / "ratchet.toml"
    scene.write_text(Path(FIXTURE).read_text(encoding="utf-8"), encoding="utf-8")
    (folder / "draft.txt").write_text("my notes", encoding="utf-8")
    (folder / "figures").mkdir()
    assert main(["run", str(scene), "--out", str(folder), "--only", "errors"]) == 0
    assert {"ratchet.toml", "draft.txt", "figures", "errors.md", "results.json"} <= {p.name for p in folder.iterdir()}
    assert (folder / "draft.txt").read_text(encoding="utf-8") == "my notes"
    (folder / "note-latex.pdf").write_bytes(b"%PDF")  # xelatex run in the folder, as the guide says
    assert main(["run", str(scene), "--out", str(folder), "--only", "positions"]) == 0
    left = {p.name for p in folder.iterdir()}
    assert {"ratchet.toml", "draft.txt", "figures", "note-latex.pdf", "positions.svg", "results.json"} <= left
    assert not {"errors.md", "errors.csv"} & left  # the earlier run's, replaced
    listed = (folder / WRITTEN).read_text(encoding="utf-8").splitlines()
    assert {line.split("\t")[0] for line in listed} == {"positions.svg", "results.json"}


def test_a_run_will_not_replace_a_file_of_the_user_s_named_as_one_of_its_own(tmp_path, capsys):
    """The README promises a run keeps what no run wrote; a note.md of the user's in a folder no run had written to
    was replaced without a word. Now the run refuses and leaves the folder as it was."""
    folder = tmp_path / "project"
    folder.mkdir()
    (folder / "note.md").write_text("MY OWN NOTES", encoding="utf-8")
    (folder / "draft.txt").write_text("mine too", encoding="utf-8")
    assert main(["run", FIXTURE, "--out", str(folder), "--only", "positions"]) == 0  # writes no note.md
    capsys.readouterr()
    before = {p.name: p.read_bytes() for p in folder.iterdir()}
    assert main(["run", FIXTURE, "--out", str(folder), "--only", "note"]) == 2
    assert without_progress(capsys.readouterr().err) == (f"graphplan: error: {folder}: holds note.md, which no graphplan run wrote there "
                                       "and this run would replace; move it away, or give --out another folder\n")
    assert {p.name: p.read_bytes() for p in folder.iterdir()} == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["project"]


def test_ctrl_c_while_the_folder_is_swapped_puts_the_user_s_own_files_back(tmp_path, capsys, monkeypatch):
    """A run carries the scene and drafts beside its files into the new folder before the swap; Ctrl-C at
    the swap left them in a hidden staging folder and printed a traceback. Now the old folder is whole
    again, with the user's files in it, and the run says it was interrupted (exit status 130)."""
    folder = tmp_path / "project"
    folder.mkdir()
    scene = folder / "ratchet.toml"
    scene.write_text(Path(FIXTURE).read_text(encoding="utf-8"), encoding="utf-8")
    (folder / "draft.txt").write_text("my notes", encoding="utf-8")
    assert main(["run", str(scene), "--out", str(folder), "--only", "positions"]) == 0
    before = {p.name: p.read_bytes() for p in folder.iterdir()}
    rename = Path.rename

    def interrupted_at_the_swap(self, target):
        if Path(target).name.startswith(".project.old-"):
            raise KeyboardInterrupt
        return rename(self, target)

    monkeypatch.setattr(Path, "rename", interrupted_at_the_swap)
    assert main(["run", str(scene), "--out", str(folder), "--only", "errors"]) == 130
    assert without_progress(capsys.readouterr().err) == "graphplan: interrupted\n"
    assert {p.name: p.read_bytes() for p in folder.iterdir()} == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["project"]


def test_ctrl_c_while_cairo_writes_a_png_is_an_interruption_too(tmp_path, capsys, monkeypatch):
    """cairo writes a PNG through a Python callback that no exception leaves: Ctrl-C there printed cffi's
    traceback and ended in cairo's write error (OSError, exit status 1). Now the run says it was interrupted
    and leaves no folder, as an interruption anywhere else does."""
    # The callback is made by the module whose write_to_png cairosvg calls, patched there: a test on the same worker
    # that takes cairo's packages out of sys.modules and puts them back can leave another module under that name.
    cairo_surface = pytest.importorskip("cairosvg.surface").cairo.Surface
    cairocffi_surfaces = cairo_surface.write_to_png.__globals__
    make_write_func = cairocffi_surfaces["_make_write_func"]

    def interrupted_while_writing(target):
        class Interrupted:
            def write(self, data):
                signal.raise_signal(signal.SIGINT)  # as a Ctrl-C from the terminal: handled inside the callback
                return target.write(data)

        return make_write_func(Interrupted())

    monkeypatch.setitem(cairocffi_surfaces, "_make_write_func", interrupted_while_writing)
    handler_before = signal.getsignal(signal.SIGINT)
    # A suite started in the background (`&`, nohup) has Ctrl-C ignored from its start: a terminal's is put in.
    assert handler_before in (signal.default_int_handler, signal.SIG_IGN), "a test before left its Ctrl-C handler"
    folder = tmp_path / "project"
    signal.signal(signal.SIGINT, signal.default_int_handler)
    try:
        status = main(["run", FIXTURE, "--out", str(folder), "--only", "positions", "--format", "png"])
    finally:
        signal.signal(signal.SIGINT, handler_before)
    assert status == 130
    assert without_progress(capsys.readouterr().err) == "graphplan: interrupted\n"
    assert list(tmp_path.iterdir()) == []


def test_an_output_folder_given_as_a_link_is_written_through_the_link(tmp_path):
    """A link to a folder was replaced by a folder of the run's, the user's files moved out of the folder it named
    and the old folder left behind as .link.old-PID. Now the run writes into the folder the link names."""
    from graphplan.output import WRITTEN

    real = tmp_path / "real"
    real.mkdir()
    (real / "keep.txt").write_text("mine", encoding="utf-8")
    link = tmp_path / "link"
    link.symlink_to("real", target_is_directory=True)
    for only in ("positions", "errors"):  # a second run replaces the first's files, still through the link
        assert main(["run", FIXTURE, "--out", str(link), "--only", only]) == 0
    assert link.is_symlink() and link.readlink() == Path("real")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["link", "real"]
    assert {p.name for p in real.iterdir()} == {"keep.txt", WRITTEN, "errors.md", "errors.csv", "errors.tex", "results.json"}
    assert (real / "keep.txt").read_text(encoding="utf-8") == "mine"


@pytest.mark.parametrize("command", ["run", "check"])
def test_an_unknown_option_of_a_command_is_told_with_that_command_s_usage(capsys, command):
    """It printed the top-level usage, "graphplan [-h] COMMAND ...", which names none of the command's options."""
    with pytest.raises(SystemExit) as stopped:
        main([command, FIXTURE, "--bogus"])
    assert stopped.value.code == 2
    err = capsys.readouterr().err
    assert err.startswith(f"usage: graphplan {command} [-h]")
    assert err.endswith(f"graphplan {command}: error: unrecognized arguments: --bogus\n")


def test_a_run_will_not_replace_the_folder_it_runs_in(tmp_path, capsys, monkeypatch):
    scene = tmp_path / "ratchet.toml"
    scene.write_text(Path(FIXTURE).read_text(encoding="utf-8"), encoding="utf-8")
    monkeypatch.chdir(tmp_path)
    for out in (".", str(tmp_path.parent)):
        assert main(["run", "ratchet.toml", "--out", out, "--only", "errors"]) == 2
        assert "is the folder the command runs in (or holds it)" in capsys.readouterr().err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["ratchet.toml"]


@pytest.mark.parametrize("kind", ["rotor", "flywheel"])
def test_figures_of_a_machine_without_a_mechanism_are_refused_naming_the_flag_given(tmp_path, capsys, kind):
    """--figures on a rotor's scene said "--only[3]: 'figures' needs a mechanism", naming an option never typed;
    it names --figures, and writes nothing, as any refused run."""
    from graphplan.starters import starter

    scene = tmp_path / f"{kind}.toml"
    scene.write_text(starter(kind), encoding="utf-8")
    capsys.readouterr()
    assert main(["run", str(scene), "--out", str(tmp_path / "out"), "--figures"]) == 2
    error = without_progress(capsys.readouterr().err).strip().splitlines()
    assert error == ["graphplan: error: --figures: 'figures' needs a mechanism: the scene has no [frame] and [driver]"]
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("only, kind", [("positions", "docx"), ("accuracy", "dxf")])
def test_a_format_none_of_the_pieces_comes_in_is_said_not_dropped(tmp_path, capsys, only, kind):
    """--only positions --format docx wrote no note.docx and --only accuracy --format dxf no DXF, without a word;
    the run says so, and writes what it would (PNG, where a drawing is asked, still comes)."""
    out = tmp_path / "out"
    capsys.readouterr()
    assert main(["run", "fixtures/ratchet_crank_rocker.toml", "--out", str(out), "--only", only,
                 "--format", f"{kind},png"]) == 0
    told = [line for line in capsys.readouterr().out.splitlines() if line.startswith("warning: --format")]
    assert told == [(f"warning: --format {kind}: nothing this run writes comes as {kind} (the pieces it writes: "
                     f"{only})")]
    assert not list(out.glob(f"*.{kind}")) and list(out.glob("*.png"))


def test_only_results_is_told_that_every_run_writes_them(tmp_path, capsys):
    """--only results, for the numbers alone, was refused as a misspelt piece among fifteen."""
    out = tmp_path / "out"
    assert main(["run", FIXTURE, "--only", "positions,results", "--out", str(out)]) == 2
    error = capsys.readouterr().err
    assert error.startswith("graphplan: error: --only[1]: results.json is written by every run, beside the pieces "
                            "named: name those, or positions alone for the least beside it")
    assert not out.exists()
    # As told: positions alone writes results.json, the analysis of every position in it.
    assert main(["run", FIXTURE, "--only", "positions", "--out", str(out)]) == 0
    written = sorted(path.name for path in out.iterdir() if not path.name.startswith("."))
    assert written == ["positions.svg", "results.json"]
    assert json.loads((out / "results.json").read_text(encoding="utf-8"))["positions"]
