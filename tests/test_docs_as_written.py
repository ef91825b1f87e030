"""What the README, the course project and the starters tell a student to do works as they print it.

A student follows README.md's commands and Python from the top, in one folder, as they stand; the course project's
table of files is the whole of what its run writes; a starter's comment that says how to change it is done as it
says and the scene then runs.  (docs/scene-format.md's own examples and the course project's walk-through are run by
tests/test_docs.py.)
"""

from __future__ import annotations

import cmath
import io
import json
import math
import re
import shlex
import sys
import tomllib
from pathlib import Path
from xml.etree import ElementTree

import pytest

import graphplan
from graphplan.analysis import analyse
from graphplan.cli import EXAMPLES, main
from graphplan.starters import KINDS, starter

ROOT = Path(__file__).resolve().parent.parent
README = (ROOT / "README.md").read_text(encoding="utf-8")
COURSE = (ROOT / "docs" / "course-project.md").read_text(encoding="utf-8")


def fenced(text: str, language: str) -> list[str]:
    return re.findall(rf"```{language}\n(.*?)```", text, flags=re.DOTALL)


def graphplan_commands(block: str) -> list[tuple[list[str], str]]:
    """Each graphplan command of a shell block as its words, with the comment printed beside it: the pip and
    pytest commands around them are the installation's, not the program's."""
    commands = []
    for line in block.strip().splitlines():
        code, _, comment = line.partition("#")
        for part in code.split("&&"):
            words = shlex.split(part)
            if words[:3] == ["python3", "-m", "graphplan"]:
                words = words[2:]
            if words and words[0] == "graphplan":
                commands.append((words[1:], comment.strip()))
    return commands


def svg_texts(path: Path) -> str:
    return " ".join(element.text or "" for element in ElementTree.parse(path).getroot().iter())


@pytest.fixture
def student_folder(tmp_path, monkeypatch):
    """An empty folder of the student's with the project's fixtures in it, as the README's commands expect."""
    (tmp_path / "fixtures").symlink_to(ROOT / "fixtures", target_is_directory=True)
    monkeypatch.chdir(tmp_path)
    return tmp_path


def piped(words: list[str]) -> tuple[list[str], Path | None]:
    """A command's words before the shell's ``< file``, and the file it pipes into standard input."""
    if "<" not in words:
        return words, None
    at = words.index("<")
    return words[:at], Path(words[at + 1])


def run_as_printed(words: list[str], capsys) -> str:
    words, stdin = piped(words)
    with pytest.MonkeyPatch.context() as patch:
        if stdin is not None:
            patch.setattr(sys, "stdin", io.TextIOWrapper(io.BytesIO(stdin.read_bytes())))
        assert main(words) == 0, " ".join(words)
    return capsys.readouterr().out


def scene_file(words: list[str]) -> Path:
    """The scene file a run or check reads: its path, or the file piped in for ``-``."""
    words, stdin = piped(words)
    return stdin if words[1] == "-" and stdin is not None else Path(words[1])


def out_folder(words: list[str]) -> Path:
    words, _ = piped(words)
    if "--out" in words:
        return Path(words[words.index("--out") + 1])
    return Path("output") / ("stdin" if words[1] == "-" else Path(words[1]).stem)


def test_the_readme_commands_run_in_order_and_write_what_they_say(student_folder, capsys):
    """``graphplan new shaper --locale zh`` after ``graphplan new shaper`` stopped at 'shaper.toml: exists already':
    the README's list, run from the top, failed on its eighth line."""
    commands = [command for block in fenced(README, "sh") for command in graphplan_commands(block)]
    assert sum(words[0] == "new" for words, _ in commands) >= 5
    for words, comment in commands:
        printed = run_as_printed(words, capsys)
        if words[0] == "check":
            assert f"{'<stdin>' if words[1] == '-' else words[1]}: ok" in printed and "structure: I(1,2)" in printed
        elif words[0] == "new":
            locale = words[words.index("--locale") + 1] if "--locale" in words else "en"
            written = Path(words[words.index("--out") + 1]) if "--out" in words else Path(f"{words[1]}.toml")
            assert written.read_text(encoding="utf-8") == starter(words[1], locale)
        else:
            folder = out_folder(words)
            # "→ output/ratchet_crank_rocker/", "in shaper/": the folder the comment names is the one written.
            for named in re.findall(r"(\S+)/$", comment):
                assert Path(named) == folder
            names = {path.name for path in folder.iterdir() if not path.name.startswith(".")}
            assert "results.json" in names
            plans = tomllib.loads(scene_file(words).read_text(encoding="utf-8"))["positions"]["plans"]
            if "--only" in words and set(words[words.index("--only") + 1].split(",")) <= {"velocity", "acceleration"}:
                assert {name.split(".")[0] for name in names} - {"results"} == {f"plan_{index}" for index in plans}
            formats = words[words.index("--format") + 1].split(",") if "--format" in words else []
            if "png" in formats:
                drawings = {name.removesuffix(".svg") for name in names if name.endswith(".svg")}
                assert drawings and {name + ".png" for name in drawings} <= names
            if "--locale" in words and words[words.index("--locale") + 1] == "ru":
                assert re.search("[а-яА-Я]", svg_texts(folder / f"plan_{plans[0]}.svg"))
            if "--sheet" in words:
                # The ISO sizes laid across: A1 841 × 594 mm, A2 594 × 420, A3 420 × 297.
                width = {"A1": "841mm", "A2": "594mm", "A3": "420mm"}[words[words.index("--sheet") + 1]]
                assert ElementTree.parse(folder / "sheet_1.svg").getroot().get("width") == width
            elif "--only" not in words:
                assert "sheet_1.svg" in names   # the fixtures name [drawing] sheet: a run draws the sheets


def test_the_readme_python_runs_in_order_and_gives_what_its_comments_say(student_folder, capsys):
    """The README's Python, its blocks in order in one namespace (the last uses the first's scene), after the
    ``graphplan new rotor`` its comment names; the rotor's numbers against the textbook's formulas."""
    run_as_printed(["new", "rotor"], capsys)
    namespace: dict = {}
    for block in fenced(README, "python"):
        exec(block, namespace)   # noqa: S102 - the README's own example, as printed
    motion = namespace["motion"]
    assert motion.point("B").v.shape == (36000, 2) and motion.link(4).epsilon.shape == (36000,)
    assert namespace["five"].values["VB"] > 0 and Path("plan_5.png").read_bytes()[:4] == b"\x89PNG"
    assert Path("diagrams.png").read_bytes()[:4] == b"\x89PNG"
    strokes = namespace["analysis"].strokes
    assert strokes.working + strokes.idle == pytest.approx(2 * math.pi)   # a crank's turn, in radians

    # Plane L's correction, kg·m and degrees: −Σ mi·ri·(zR − zi)/(zR − zL) over the starter's masses.
    tables = tomllib.loads(Path("rotor.toml").read_text(encoding="utf-8"))
    balancing = tables["balancing"]
    left, right = balancing["planes"]
    share = sum(mass["mass"] * cmath.rect(mass["radius"], math.radians(mass["angle"])) * (right - mass["plane"])
                for mass in balancing["masses"]) / (right - left)
    plane = namespace["balancing"].planes[0]
    assert plane.mass_radius == pytest.approx(abs(share), rel=1e-9)
    assert math.radians(plane.angle_deg) % math.tau == pytest.approx(cmath.phase(-share) % math.tau, abs=1e-9)
    assert namespace["balancing"].results["planes"][0]["mass_radius"] == pytest.approx(abs(share), rel=1e-9)

    # X = (m·e/M)·r²/√((1 − r²)² + (2ζr)²), in metres.
    shaking = tables["vibration"]
    r = shaking["rpm"] * math.pi / 30 / math.sqrt(shaking["stiffness"] / shaking["mass"])
    zeta = shaking["damping_ratio"]
    amplitude = shaking["unbalance"] / shaking["mass"] * r ** 2 / math.hypot(1 - r ** 2, 2 * zeta * r)
    assert namespace["shaking"].response.amplitude == pytest.approx(amplitude, rel=1e-9)
    assert Path("magnification.png").read_bytes()[:4] == b"\x89PNG"

    done = namespace["done"]
    assert Path("ratchet", "plan_5.png") in done.files and all(path.exists() for path in done.files)
    assert {path.name for path in Path("ratchet").iterdir()} >= {"note.md", "plan_5.svg", "results.json"}
    # The ratchet has no [dynamics], [balancing] or [vibration]: whichever pieces, its results are the same.
    assert namespace["numbers"] == json.loads(Path("ratchet", "results.json").read_text(encoding="utf-8"))


def test_the_command_lines_examples_run_as_printed(student_folder, capsys):
    """``graphplan --help``'s examples (cli.EXAMPLES), run in order in one folder with the fixtures, each run's
    folder looked at before the next replaces it."""
    lines = [re.split(r"\s{3,}", line.strip())[0] for line in EXAMPLES.splitlines()[1:] if line.strip()]
    assert len(lines) >= 8
    for line in lines:
        words = shlex.split(line)
        assert words[0] == "graphplan"
        run_as_printed(words[1:], capsys)
        if words[1] == "run":
            folder = out_folder(words[1:])
            names = {path.name for path in folder.iterdir() if not path.name.startswith(".")}
            assert "results.json" in names
            if "pdf" in line:
                assert "note.pdf" in names and any(name.startswith("sheet_") and name.endswith(".dxf")
                                                   for name in names)
            if "docx" in line:
                assert "note.docx" in names
        elif words[1] == "new":
            assert Path(f"{words[2]}.toml").exists()


def test_every_file_of_the_course_project_s_run_is_in_its_table(student_folder, capsys):
    """The table of what ``graphplan run shaper.toml --out shaper`` writes left out load_diagrams.svg, which the
    starter's windowed cutting force draws; a drawing's parts for the note (``forces_3-1.svg``) are its own."""
    run_as_printed(["new", "shaper"], capsys)
    run_as_printed(["run", "shaper.toml", "--out", "shaper"], capsys)
    table = COURSE.split("writes into `shaper/`:", 1)[1].split("\n\n", 2)[1]

    def pattern(name: str) -> str:
        return re.sub(r"\d+", "N", name)

    listed = {pattern(name) for cell in re.findall(r"^\| ([^|]*) \|", table, flags=re.MULTILINE)
              for name in re.findall(r"`([^`]+)`", cell)}
    written = {pattern(re.sub(r"-\d+(?=\.\w+$)", "", path.name)) for path in Path("shaper").iterdir()
               if not path.name.startswith(".")}   # but the run's own list of what it wrote
    assert written - listed == set()


TRIAD_COMMENT = " ".join(line.lstrip("# ") for line in starter("triad").splitlines() if line.startswith("#"))


def triad_as_the_comment_says(guides: str, lengths: str, centres: dict[int, str]) -> str:
    """The triad starter changed as its comment says a leg is made to slide: the guides, the lengths of the legs
    left turning, each slider's centre at its pin, E moved onto F's line, and the load made a force on F."""
    text = starter("triad")
    (moved,) = re.findall(r"(E = \[[\d., ]+\]), on the line", TRIAD_COMMENT)
    text = re.sub(r"E = \[[\d., ]+\]", moved, text, count=1)
    text = text.replace("lengths = [0.135, 0.108, 0.189]", f"lengths = {lengths}\nguides = {guides}")
    for link, centre in centres.items():
        text = re.sub(rf"\nS{link} = .*\n", "\n", text).replace(f'centre  = "S{link}"', f'centre  = "{centre}"')
    (load,) = re.findall(r"`(kind = \"force\"`.*?`angle = [-\d.]+)`", TRIAD_COMMENT)
    force = "\n".join(item.strip("` ") for item in load.split(","))
    moment = re.search(r'kind      = "moment"\nlink      = 5\nvalue .*\n', text)[0]
    return text.replace(moment, f"{force}\nlink = 5\n")


@pytest.mark.parametrize("sliding", ["F", "D and F"])
def test_the_triad_starter_s_advice_on_sliding_legs_runs(sliding):
    """The starter said a leg slides with ``guides = { F = { angle = 0.0 } }`` and E on its line: done so, the
    moment on link 5 was refused (link 5 no longer turns), and with a force in its place no angle of the crank
    assembled the group on a line through E where the starter has it."""
    (one,) = re.findall(r"is `(guides = \{ F = \{ angle = [-\d.]+ \} \})`", TRIAD_COMMENT)
    (one_lengths,) = re.findall(r"with `lengths = (\[[\d., ]+\])` listing", TRIAD_COMMENT)
    assert '`centre = "F"` under [links.5], S5 left out' in TRIAD_COMMENT
    (two, two_lengths) = re.findall(r"Two legs may slide \(`guides = (.*?)`, `lengths = (\[[\d., ]+\])`",
                                    TRIAD_COMMENT)[0]
    assert '`centre = "D"` under [links.4], S4 left out' in TRIAD_COMMENT
    if sliding == "F":
        text = triad_as_the_comment_says(one.split("=", 1)[1].strip(), one_lengths, {5: "F"})
        expected = [(5, 1, "F")]
    else:
        text = triad_as_the_comment_says(two, two_lengths, {4: "D", 5: "F"})
        expected = [(4, 1, "D"), (5, 1, "F")]
    analysis = analyse(graphplan.load_text(text))
    assert [(slide.slider, slide.guide, slide.joint) for slide in analysis.motion.slides] == expected
    assert not analysis.warnings
    rows = [row for row in analysis.errors if row.source == "construction"]
    assert rows and max(abs(row.percent) for row in rows) < 1e-9
    # The force resists the slider's motion along its guide: the balancing moment does work against it.
    assert analysis.equilibrium.balancing is not None


def test_the_rotor_starter_s_advice_on_its_planes_is_what_a_run_does():
    """The starter said to leave ``planes`` out for static balancing; its masses lie in three planes, so that is
    refused: one plane ``[z]`` balances the force and leaves a couple, and only a disc leaves planes out."""
    text = starter("rotor")
    comment = " ".join(line.split("#", 1)[1] for line in text.splitlines() if "#" in line)
    assert "planes = [z]" in comment and "planes left out only for a disc" in comment
    with pytest.raises(graphplan.GraphplanError, match=r"balancing\.planes: is required"):
        graphplan.load_text(text.replace("planes = [0.04, 0.22]", "")).balance()
    static = graphplan.load_text(text.replace("planes = [0.04, 0.22]", "planes = [0.1]")).balance().results
    assert static["kind"] == "static" and [w["code"] for w in static["warnings"]] == ["couple-left"]
    disc = re.sub(r"plane = [\d.]+ \}", "plane = 0.0 }", text.replace("planes = [0.04, 0.22]", ""))
    assert graphplan.load_text(disc).balance().results["kind"] == "static"


def test_the_starters_run_without_a_warning_in_every_language(tmp_path, capsys):
    """A starter is the scene a newcomer begins from: a warning on it would be one the student did not cause."""
    for kind in KINDS:
        for locale in ("en", "ru", "zh"):
            scene = tmp_path / f"{kind}-{locale}.toml"
            assert main(["new", kind, "--locale", locale, "--out", str(scene)]) == 0
            assert main(["check", str(scene)]) == 0
            told = capsys.readouterr()
            assert "warning" not in told.out + told.err, (kind, locale)


def test_the_sheet_option_draws_the_sheets_as_its_help_says(student_folder, capsys):
    """``--sheet``'s help said the run 'also draws' the sheets: with ``--only`` that leaves them out it draws none,
    as the help now says; without, a scene whose ``[drawing] sheet`` is "none" gets them."""
    with pytest.raises(SystemExit):
        main(["run", "--help"])
    helped = " ".join(capsys.readouterr().out.split())
    assert "which it then draws unless --only or the scene's [output] include leaves out 'sheets'" in helped
    scene = Path("engine.toml")
    text = (ROOT / "fixtures" / "engine_slider_crank.toml").read_text(encoding="utf-8")
    scene.write_text(re.sub(r'(?m)^sheet\s*=.*$', 'sheet = "none"', text), encoding="utf-8")
    run_as_printed(["run", str(scene), "--sheet", "A1", "--only", "positions", "--out", "only"], capsys)
    assert not list(Path("only").glob("sheet_*"))
    run_as_printed(["run", str(scene), "--sheet", "A1", "--out", "all"], capsys)
    assert ElementTree.parse(Path("all", "sheet_1.svg")).getroot().get("width") == "841mm"
    # README: the sheets "when the scene names [drawing] sheet or --sheet a format, or with --only sheets, on A1 where
    # neither names one"; a scene that names none asked for them alone got A1 sheets without a word of it.
    assert "or with `--only sheets`, on A1 where neither names one" in " ".join(README.split())
    scene.write_text(re.sub(r'(?m)^sheet\s*=.*$', "", text), encoding="utf-8")
    run_as_printed(["run", str(scene), "--only", "sheets", "--out", "asked"], capsys)
    assert ElementTree.parse(Path("asked", "sheet_1.svg")).getroot().get("width") == "841mm"


def test_the_readme_names_every_bundled_scene():
    """The README's list of fixtures left out the double rocker rocked over a swing, the one scene of a rocking
    crank: a student looking for one was told there is none."""
    listed = set(re.findall(r"`(\w+\.toml)`", README.split("## Fixtures", 1)[1].split("\n## ", 1)[0]))
    assert listed == {path.name for path in (ROOT / "fixtures").glob("*.toml")}


def test_the_readme_names_every_benchmark():
    """The README's benchmarks left out bench/positions_count.py, whose results the extensions cite for the limit of
    20 000 positions, and bench/label_clutter.py: each script a user runs is named with the command that runs it."""
    section = README.split("## Benchmarks", 1)[1].split("\n## ", 1)[0]
    named = set(re.findall(r"`python (bench/\w+\.py)`", section))
    # peers.py is the peer packages' solvers, which sweep.py runs through; its own main is a self-check.
    scripts = {f"bench/{path.name}" for path in (ROOT / "bench").glob("*.py")
               if '__name__ == "__main__"' in path.read_text(encoding="utf-8") and path.stem != "peers"}
    assert len(scripts) >= 10 and named == scripts


def test_a_machine_run_down_to_rest_shows_its_speed_as_0_not_rounding():
    """``scene.machine_dynamics().motion``, which the README offers, showed ``ω -1.11e-15 … 6.377 rad/s`` of the
    shaper switched off and run down to rest: the integration's rounding, which results.json writes as 0."""
    text = starter("shaper")
    motor = re.search(r"(?m)^motor = .*$", text)[0]
    motion = graphplan.load_text(text.replace(motor, motor.replace(" }", ", off_at = 6.0 }"))).machine_dynamics().motion
    assert motion.stopped_at is not None
    assert abs(float(motion.omega.min())) < 1e-12 * float(motion.omega.max())
    assert re.search(r", ω 0 … [\d.]+ rad/s, at rest from ", repr(motion)), repr(motion)


def test_scene_write_s_locale_and_sheet_write_what_the_command_line_s_do(student_folder, capsys):
    """README: ``scene.write`` takes ``locale`` and ``sheet`` as ``graphplan run`` takes ``--locale`` and ``--sheet``,
    through the same code, to the same files: byte for byte, a Chinese note and A3 sheets of a scene in English on
    A2, with the GB/T title block the Chinese sheets carry."""
    scene = "fixtures/engine_slider_crank.toml"
    run_as_printed(["run", scene, "--only", "positions,note,sheets", "--locale", "zh", "--sheet", "A3",
                    "--out", "by_command"], capsys)
    graphplan.load(scene).write("by_python", only=["positions", "note", "sheets"], locale="zh", sheet="A3")
    written = {path.name: path.read_bytes() for path in Path("by_command").iterdir()}
    assert {path.name: path.read_bytes() for path in Path("by_python").iterdir()} == written
    assert "sheet_1.svg" in written and re.search("[\u4e00-\u9fff]", written["note.md"].decode("utf-8"))
    sheet = ElementTree.parse(Path("by_python", "sheet_1.svg")).getroot()
    assert sheet.get("width") == "420mm" and "设计" in svg_texts(Path("by_python", "sheet_1.svg"))


def test_the_title_blocks_carry_the_project_s_people_as_the_extensions_say():
    """The extensions listed the boxes each title block fills; an English project's checked_by was on no sheet and
    the page did not say so: ESKD's and GB/T's blocks carry the checker, ISO 7200's, which has no box for one, not."""
    from graphplan.render.primitives import Text
    from graphplan.render.title_block import TitleBlockFields, labels, title_block

    extensions = (ROOT / "docs" / "scene-format-extensions.md").read_text(encoding="utf-8")
    assert "ISO 7200 has no box for who checked the drawing, so an English sheet leaves `checked_by`" in extensions
    fields = TitleBlockFields(title="Shaper", author="Author", checked_by="Checker", approved_by="Approver",
                              drawing="Kinematic analysis", scale="1:2", sheet=1, sheets=1)
    for form, locale in (("eskd", "ru"), ("gb", "zh"), ("iso", "en")):
        texts = " ".join(item.text for item in title_block(form, fields, labels(locale), (420.0, 0.0))
                         if isinstance(item, Text))
        assert "Author" in texts and "Approver" in texts
        assert ("Checker" in texts) == (form != "iso"), form
