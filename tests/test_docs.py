"""The scene format the project documents (docs/scene-format.md) is true of graphplan.

The page is the public contract of the scene and results files, kept in the repository word for word
as the design gives it, so that a reader of the project has it.  Its example scene runs, the results it
shows are the keys a run writes, and its Python example works as printed.
"""

from __future__ import annotations

import json
import math
import re
from pathlib import Path

import numpy as np
import pytest

from graphplan.cli import main
from graphplan.scene import loads

ROOT = Path(__file__).resolve().parent.parent
PAGE = ROOT / "docs" / "scene-format.md"
# The design's own copy, where the project sits beside it (not in a clean checkout).
CONTRACT = ROOT.parent / "shared" / "scene-format.md"


def fenced(language: str) -> list[str]:
    return re.findall(rf"```{language}\n(.*?)```", PAGE.read_text(encoding="utf-8"), flags=re.DOTALL)


def test_the_page_is_the_contract_word_for_word():
    if not CONTRACT.exists():
        pytest.skip("the design's scene-format.md is not beside this checkout")
    assert PAGE.read_text(encoding="utf-8") == CONTRACT.read_text(encoding="utf-8")


def key_paths(node, path=""):
    """Every key of a JSON document as a path, list items under ``[]``."""
    if isinstance(node, dict):
        for key, value in node.items():
            yield f"{path}.{key}"
            yield from key_paths(value, f"{path}.{key}")
    elif isinstance(node, list):
        for value in node:
            yield from key_paths(value, f"{path}[]")


@pytest.fixture(scope="module")
def example_results(tmp_path_factory) -> dict:
    """The results of the page's example scene, run as a student would."""
    scene_text, = fenced("toml")
    loads(scene_text)   # every key of the example is one the reader accepts
    folder = tmp_path_factory.mktemp("example")
    scene = folder / "example.toml"
    scene.write_text(scene_text, encoding="utf-8")
    assert main(["run", str(scene), "--out", str(folder / "out"), "--only", "forces,errors"]) == 0
    return json.loads((folder / "out" / "results.json").read_text(encoding="utf-8"))


def test_the_example_scene_runs_and_writes_the_results_keys_the_page_shows(example_results):
    written = example_results
    shown = json.loads(fenced("json")[0])
    # The page's point "B", link "3" and reaction "R23" stand for every one: their names are the example's.
    def generic(document) -> set[str]:
        return {re.sub(r"\.(points|links|reactions)\.[^.]+", r".\1.*", path) for path in key_paths(document)}

    shown_paths, written_paths = generic(shown), generic(written)
    if not written["warnings"]:   # the example's scene runs without a warning: the list is empty
        shown_paths = {path for path in shown_paths if not path.startswith(".warnings[]")}
    assert shown_paths <= written_paths, sorted(shown_paths - written_paths)


def _example_kinematics(phi: float) -> dict[str, float]:
    """The example's four-bar at crank angle ``phi`` (rad), worked here from its lengths alone: B where the circles
    of AB about A and BC about C cross, left of A→C; its velocity and acceleration, ω4 and ε4 by central differences
    of the closed form in φ (ω = −17 rad/s, ε = 0)."""
    omega, crank, ab, bc, c = -17.0, 0.175, 0.55, 0.325, 0.55j

    def joint_b(angle: float) -> complex:
        a = crank * np.exp(1j * angle)
        to_c = c - a
        spread = np.arccos((ab ** 2 + abs(to_c) ** 2 - bc ** 2) / (2.0 * ab * abs(to_c)))
        return a + ab * np.exp(1j * (np.angle(to_c) + spread))

    def rocker(angle: float) -> float:
        return float(np.angle(joint_b(angle) - c))

    h = 1e-4
    b = [joint_b(phi + k * h) for k in (-1, 0, 1)]
    rock = np.unwrap([rocker(phi + k * h) for k in (-1, 0, 1)])
    return {"angle_deg": math.degrees(np.angle(b[1] - crank * np.exp(1j * phi))) % 360.0,
            "VB": abs((b[2] - b[0]) / (2 * h)) * abs(omega),
            "omega4": (rock[2] - rock[0]) / (2 * h) * omega,
            "aB": abs((b[2] - 2 * b[1] + b[0]) / h ** 2) * omega ** 2,
            "epsilon4": (rock[2] - 2 * rock[1] + rock[0]) / h ** 2 * omega ** 2}


def test_the_values_the_extensions_give_for_the_example_are_its_run_s(example_results):
    """The contract's example results show the file's form with numbers of their own (link 3 at 48.5°, a balancing
    moment of 412 N·m); the extensions page gives the example scene's own, which a student running it finds, its
    kinematics checked here against the four-bar worked from its lengths."""
    extensions = (ROOT / "docs" / "scene-format-extensions.md").read_text(encoding="utf-8")
    row = next(line for line in extensions.splitlines() if line.startswith("| the contract's example results |"))
    values, _, hand = row.partition("; its `[measured.5]`")
    given = {key: float(value.replace("−", "-")) for key, value in re.findall(r"`(\w+)`(?: of)? (−?[\d.]+)", values)}
    position, = (entry for entry in example_results["positions"] if entry["index"] == 5)
    velocity, acceleration = position["plans"]["velocity"], position["plans"]["acceleration"]["values"]
    run = {"angle_deg": position["links"]["3"]["angle_deg"], "VB": velocity["values"]["VB"],
           "omega4": velocity["values"]["omega4"], "aB": acceleration["aB"], "epsilon4": acceleration["epsilon4"],
           "balancing_moment": position["forces"]["balancing_moment"]}
    assert set(given) == set(run), row
    for key, value in given.items():
        digits = len(str(value).split(".")[1])
        assert run[key] == pytest.approx(value, abs=0.51 * 10.0 ** -digits), key
        if key in (exact := _example_kinematics(math.radians(position["driver"]["angle_deg"]))):
            assert exact[key] == pytest.approx(value, abs=0.51 * 10.0 ** -digits), key
    # The hand reading: pb (mm) at the plan's μV over lBC, and its δ against the analytic ω4.
    reading = re.search(r"pb = ([\d.]+) mm reads `omega4` ([\d.]+) rad/s \(\1 mm · ([\d.]+) \(m/s\)/mm / lBC "
                        r"([\d.]+) m\), δ (−[\d.]+) %", hand)
    assert reading is not None, row
    pb, omega4, scale, length, percent = (float(value.replace("−", "-")) for value in reading.groups())
    assert velocity["scale"] == pytest.approx(scale, rel=1e-4)
    assert pb * velocity["scale"] / length == pytest.approx(omega4, abs=0.005)
    measured, = (row for row in example_results["errors"]
                 if (row["position"], row["quantity"], row["source"]) == (5, "omega4", "measured"))
    assert measured["plan"] == pytest.approx(omega4)
    assert measured["percent"] == pytest.approx(percent, abs=0.005)
    assert percent == pytest.approx((run["omega4"] - omega4) / run["omega4"] * 100.0, abs=0.005)


def test_the_python_example_works_as_printed(monkeypatch):
    code, = fenced("python")
    monkeypatch.chdir(ROOT)
    namespace: dict = {}
    exec(code, namespace)   # noqa: S102 - the page's own example, as printed
    motion, omega = namespace["motion"], namespace["scene"].driver.omega
    b, link = motion.point("B"), motion.link(4)
    assert b.r.shape == b.v.shape == b.a.shape == (36000, 2)
    assert link.angle.shape == link.omega.shape == link.epsilon.shape == (36000,)
    # ω4 = dψ4/dφ · ω: the angle's derivative over the example's own step of 0.01°.
    by_difference = np.gradient(np.unwrap(link.angle), np.radians(0.01)) * omega
    assert np.allclose(by_difference[1:-1], link.omega[1:-1], rtol=1e-4, atol=1e-4 * abs(link.omega).max())


COURSE = ROOT / "docs" / "course-project.md"


def test_the_course_project_walk_through_runs_as_printed(tmp_path, monkeypatch, capsys):
    """Every ``graphplan`` line of docs/course-project.md is run in the page's order, the TOML block added to
    the scene where the page adds it; what the page says the commands print and write is checked."""
    import shlex
    from xml.etree import ElementTree

    page = COURSE.read_text(encoding="utf-8")
    monkeypatch.chdir(tmp_path)
    printed = []
    for language, block in re.findall(r"```(sh|toml)\n(.*?)```", page, flags=re.DOTALL):
        if language == "toml":
            with open("shaper.toml", "a", encoding="utf-8") as scene:
                scene.write("\n" + block)
            continue
        for line in block.strip().splitlines():
            words = shlex.split(line)
            assert words[0] == "graphplan"
            assert main(words[1:]) == 0, line
            printed.append(capsys.readouterr().out)
    assert "structure: I(1,2) → II2(3,4) → II2(5,6)\nW = 3n − 2p5 − p4 = 3·5 − 2·7 − 0 = 1" in printed[1]
    shown = re.search(r"`(working φw = .*?)`", page)[1]
    assert f"strokes: {shown}" in printed[1]
    listed = set(re.findall(r"^\| `([^`]+)`", page, flags=re.MULTILINE))
    written = {path.name for path in (tmp_path / "shaper").iterdir()}
    for entry in listed:
        for name in re.findall(r"[\w.]+\.\w+", entry.replace("…", "")):
            assert name in written, name
    # The drawn pe at μV = VA / pa: the starter's crank, 0.10 m at 60 rpm, drawn 100 mm long.
    errors = (tmp_path / "checked" / "errors.md").read_text(encoding="utf-8")
    header = next(line for line in errors.splitlines() if line.startswith("| quantity"))
    row = next(line for line in errors.splitlines() if line.startswith("| VE |"))
    cells = dict(zip(header.split("|"), row.split("|"), strict=True))
    drawn = float(re.search(r"velocity\s*=\s*\{ pe = ([\d.]+)", page)[1])
    assert float(cells[" measured "]) == pytest.approx(drawn * (2 * np.pi * 0.10) / 100.0, rel=1e-4)
    root = ElementTree.parse(tmp_path / "shaper-ru" / "sheet_1.svg").getroot()
    assert root.get("width") == "594mm"
    # The page says the scene's title stays as typed under --locale ru, and names the Russian starter's title.
    starter_text = (tmp_path / "shaper.toml").read_text(encoding="utf-8")
    typed = re.search(r'^title\s*=\s*"([^"]+)"', starter_text, re.MULTILINE)[1]
    assert f'starter\'s "{typed}" heads the title block' in " ".join(page.split())
    assert set(typed.split()) <= set(" ".join(root.itertext()).split())
    from graphplan.starters import starter

    russian = re.search(r'^title\s*=\s*"([^"]+)"', starter("shaper", "ru"), re.MULTILINE)[1]
    assert f"its title is «{russian}»" in " ".join(page.split())
    assert (tmp_path / "report" / "note.docx").exists()


def test_the_course_project_s_stall_warning_is_the_one_printed(tmp_path, capsys):
    from graphplan.starters import starter

    shown = re.search(r"^warning: dynamics: .*\(", COURSE.read_text(encoding="utf-8"), flags=re.MULTILINE)[0]
    scene = tmp_path / "weak.toml"
    scene.write_text(starter("shaper").replace("power = 3000.0", "power = 1500.0"), encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "out"), "--only", "dynamics"]) == 0
    assert shown in capsys.readouterr().out
    # "results.json gives dynamics.motion.stalled_at (s) and stalled_at_angle_deg", the φ printed, the crank's own.
    motion = json.loads((tmp_path / "out" / "results.json").read_text(encoding="utf-8"))["dynamics"]["motion"]
    at, angle = re.search(r"stalls at t = ([\d.]+) s, φ = ([\d.]+)°", shown).groups()
    assert motion["stalled_at"] == pytest.approx(float(at), abs=5e-4)
    assert motion["stalled_at_angle_deg"] == pytest.approx(float(angle), abs=0.05)
    assert not motion["steady"]


@pytest.mark.parametrize("page", ["scene-format-extensions.md", "course-project.md"])
def test_every_row_of_the_docs_tables_stands_in_a_table(page):
    """A blank line inside the extensions' table ended it: the [project] row and every row after it were set as a
    paragraph full of pipes."""
    from markdown_it import MarkdownIt

    html = MarkdownIt("commonmark").enable("table").render((ROOT / "docs" / page).read_text(encoding="utf-8"))
    assert "<table>" in html
    assert not re.findall(r"<p>\|", html)


# A fixture of each group kind, and the line its group is written on, to put the contract's `assembly` beside.
GROUP_OF_EACH_KIND = {
    "RRR": ("ratchet_crank_rocker.toml", 'kind     = "RRR"'),
    "RRP": ("engine_slider_crank.toml", 'kind     = "RRP"'),
    "RPR": ("quick_return_slotted_lever.toml", 'kind   = "RPR"'),
    "PRP": ("tangent_mechanism_prp.toml", 'kind    = "PRP"'),
    "RPP": ("scotch_yoke.toml", 'kind   = "RPP"'),
    "triad": ("triad_class_iii.toml", 'kind    = "triad"'),
}


@pytest.mark.parametrize("kind", sorted(GROUP_OF_EACH_KIND))
def test_the_contract_s_assembly_is_taken_or_refused_with_what_chooses_the_branch(kind):
    """The contract says every group chooses its branch by ``assembly`` (left/right) or ``near``; written so on a PRP,
    an RPP or a triad it was told only 'unknown key', and on an RRP 'must be one of forward, backward', leaving the
    student to guess what does choose there."""
    import graphplan

    name, line = GROUP_OF_EACH_KIND[kind]
    text = (ROOT / "fixtures" / name).read_text(encoding="utf-8")
    assert text.count(line) == 1
    text = re.sub(r'(?m)^assembly\s*=.*$', "", text)   # the fixture's own choice, where it has one
    for side in ("left", "right"):
        written = text.replace(line, f'{line}\nassembly = "{side}"')
        if kind == "RRR":
            graphplan.load_text(written).solve()   # an RRR's B on that side of A→C: the contract's own case
            continue
        with pytest.raises(graphplan.SceneError) as refused:
            graphplan.load_text(written)
        told = str(refused.value)
        assert re.match(r"groups\[\d+\]\.assembly: ", told), told
        assert told.split(": ", 1)[1] not in ("unknown key", "must be one of forward, backward (got 'left')")
        if kind == "RRP":
            assert "forward" in told and "backward" in told and "foot of A" in told
        elif kind == "triad":
            assert "near = { B = [x, y], D = [x, y], F = [x, y] }" in told
        else:
            assert f"{'an' if kind[0] == 'R' else 'a'} {kind} has one assembly" in told


def test_an_rrp_s_forward_is_what_its_refusal_of_left_says():
    """The refusal of ``assembly = "left"`` on an RRP says forward is B ahead of the foot of A on the guide, along the
    guide's direction: so it is, at every position, and backward behind it."""
    import graphplan

    text = (ROOT / "fixtures" / "engine_slider_crank.toml").read_text(encoding="utf-8")
    with pytest.raises(graphplan.SceneError, match="ahead of the foot of A on the guide, along the guide's direction"):
        graphplan.load_text(re.sub(r'(?m)^assembly\s*=.*$', 'assembly = "left"', text))
    guide = 1.0 + 0.0j   # the fixture's cylinder axis: through O along +x
    for side, sign in (("forward", 1), ("backward", -1)):
        motion = graphplan.load_text(re.sub(r'(?m)^assembly\s*=.*$', f'assembly = "{side}"', text)).solve()
        a, b = (motion.point(joint).r @ np.array([1.0, 1.0j]) for joint in ("A", "B"))
        foot = (a * guide.conjugate()).real * guide
        assert np.all(sign * ((b - foot) * guide.conjugate()).real > 0)


EXTENSIONS = ROOT / "docs" / "scene-format-extensions.md"
README = ROOT / "README.md"


def code_names(text: str) -> set[str]:
    """The names written in the text's code spans (a span may open with several backquotes: ``` `` ` `` ```)."""
    spans = " ".join(span for _, span in re.findall(r"(`+)(.+?)\1", text))
    return set(re.findall(r"[A-Za-z_][A-Za-z0-9_]*", spans))


def results_row(key: str) -> str:
    """The row of the extensions' table of results.json that describes ``key``."""
    (row,) = [line for line in EXTENSIONS.read_text(encoding="utf-8").splitlines() if line.startswith(f"| `{key}` |")]
    return row


def named(name: str, names: set[str]) -> bool:
    """``name`` is among ``names``, or made of one and a suffix the docs give alone (``_exact``, ``_mertsalov``)."""
    return name in names or any(name.endswith(suffix) and name[:-len(suffix)] and suffix.startswith("_")
                                for suffix in names)


# Keys under these are the scene's own names (points, links, reactions, plan letters), not the file's.
NAMED_BY_THE_SCENE = {"points", "links", "reactions", "values", "points_mm", "polygon_scales", "loads", "offsets",
                      "same_as"}


def keys_under(node, path=""):
    """(path, key) of every key of a JSON document below ``path``, those under a table named by the scene left out."""
    if isinstance(node, dict):
        for key, value in node.items():
            yield path, key
            if key not in NAMED_BY_THE_SCENE:
                yield from keys_under(value, f"{path}.{key}")
    elif isinstance(node, list):
        for value in node:
            yield from keys_under(value, f"{path}[]")


@pytest.fixture(scope="module")
def documented_runs(tmp_path_factory):
    """results.json of real runs that between them write every table the docs describe: the shaper starter (friction,
    the velocity plans of every position, a flywheel and a motor), the rotor starter on a shaft and a shaken floor
    (its isolation in series with the shaft, the base's motion and both responses together), a slider driver with
    the report figures and an oscillating cylinder (its rod's ε the cylinder's: ``same_as``)."""
    from scene_texts import oscillating_cylinder

    from graphplan.starters import starter

    folder = tmp_path_factory.mktemp("documented")
    rotor = starter("rotor").replace("stiffness     = 1.0e5",
                                      "shaft = { modulus = 2.1e11, diameter = 0.03, length = 0.8 }")
    rotor = rotor.replace("transmissibility = 0.2", "transmissibility = 0.2\nbase_amplitude = 0.0005")
    scenes = {"shaper": (starter("shaper"), "dynamics"), "rotor": (rotor, "balancing,vibration"),
              "slider": ((ROOT / "fixtures" / "slider_driven.toml").read_text(encoding="utf-8"), "forces,figures"),
              "cylinder": (oscillating_cylinder(0.0), "errors")}
    runs = {}
    for name, (text, pieces) in scenes.items():
        scene = folder / f"{name}.toml"
        scene.write_text(text, encoding="utf-8")
        assert main(["run", str(scene), "--out", str(folder / name), "--only", pieces]) == 0
        runs[name] = (scene, json.loads((folder / name / "results.json").read_text(encoding="utf-8")))
    return runs


def test_every_key_a_run_writes_is_described_where_the_docs_describe_its_table(documented_runs):
    """results.json's ``dynamics`` wrote ``omega_mean`` beside the flywheel, which the extensions' row of the
    dynamics named only in the motion's steady state: every key is named in the docs, and a key of one of the tables
    the extensions describe row by row in that table's own row (the dynamics' motion in the part after ``motion``)."""
    contract, extensions = PAGE.read_text(encoding="utf-8"), EXTENSIONS.read_text(encoding="utf-8")
    everywhere = code_names(contract + extensions + README.read_text(encoding="utf-8"))
    in_the_example = set(re.findall(r'"(\w+)":', "".join(fenced("json"))))
    everywhere |= in_the_example
    dynamics, motion = results_row("dynamics").split("with a motor, `motion`:")
    rows = {".dynamics": code_names(dynamics) | {"motion"}, ".dynamics.motion": code_names(motion),
            ".versions": set(re.findall(r"\w+", results_row("versions").lower())),   # the packages, in words
            ".balancing": code_names(results_row("balancing") + results_row("balancing.warnings[]")),
            ".vibration": code_names(results_row("vibration") + results_row("vibration.warnings[]")),
            ".cycle_efficiency": code_names(results_row("cycle_efficiency")),
            ".positions[].equilibrium": code_names(results_row("positions[].equilibrium")),
            ".positions[].forces": code_names(results_row("positions[].forces") + contract) | in_the_example}
    unnamed = set()
    for name, (_, written) in documented_runs.items():
        for path, key in keys_under(written):
            table = max((table for table in rows if (path + ".").startswith(table + ".")), key=len, default=None)
            if not named(key, rows[table] if table else everywhere):
                unnamed.add(f"{name}: {path}.{key}")
    assert not unnamed, sorted(unnamed)


def test_every_key_the_results_table_and_the_readme_name_is_written(documented_runs):
    """The other way round: each key path the extensions' results table describes, and each the README says
    results.json holds, stands in a real run's file."""
    written = set()
    for _, document in documented_runs.values():
        written |= {f"{path}.{key}" for path, key in keys_under(document)}
    described = re.findall(r"^\| `([\w.\[\]]+)`", EXTENSIONS.read_text(encoding="utf-8").split("\n## Results", 1)[1],
                           flags=re.MULTILINE)
    assert len(described) > 20
    readme = re.search(r"Writes `results.json` \((.*?)\)", README.read_text(encoding="utf-8"), flags=re.DOTALL)[1]
    top, per_position = readme.split("for every position")
    told = ([f".{key}" for key in re.findall(r"`(\w+)`", top)]
            + [f".positions[].{key}" for key in re.findall(r"`(\w+)`", per_position) if key != "warnings"]
            + [".warnings"])
    missing = [path for path in [f".{key.removesuffix('[]')}" for key in described] + told if path not in written]
    assert not missing


def test_the_notebook_s_results_are_the_files_as_the_readme_says(documented_runs):
    """README: ``balancing.results`` is results.json's "balancing" and ``shaking.results`` its "vibration", as the run
    writes them; the same numbers, to the digit, from the same scene."""
    import graphplan

    scene, written = documented_runs["rotor"]
    rotor = graphplan.load(scene)
    assert rotor.balance().results == written["balancing"]
    assert rotor.vibration_response().results == written["vibration"]


def test_the_results_are_what_the_docs_formulas_make_of_the_scene(documented_runs):
    """The relations the results table states between its keys and the scene's data, worked out from the scene."""
    import math
    import tomllib

    scene, written = documented_runs["rotor"]
    machine = tomllib.loads(scene.read_text(encoding="utf-8"))["vibration"]
    vibration = written["vibration"]
    omega, mass, unbalance = machine["rpm"] * math.pi / 30, machine["mass"], machine["unbalance"]
    shaft = machine["shaft"]
    length, second_moment = shaft["length"], math.pi * shaft["diameter"] ** 4 / 64
    a = b = length / 2   # the disc midway between the bearings, simply supported
    shaft_stiffness = 3 * shaft["modulus"] * second_moment * length / (a * a * b * b)
    assert vibration["stiffness"] == pytest.approx(shaft_stiffness, rel=1e-9)
    assert vibration["natural_frequency"] == pytest.approx(math.sqrt(shaft_stiffness / mass), rel=1e-9)
    assert vibration["critical_speed_rpm"] == pytest.approx(vibration["critical_speed"] * 30 / math.pi, rel=1e-9)
    assert vibration["exciting_force"] == pytest.approx(unbalance * omega ** 2, rel=1e-9)
    ratio = omega / vibration["natural_frequency"]
    zeta = machine["damping_ratio"]
    transmissibility = math.hypot(1, 2 * zeta * ratio) / math.hypot(1 - ratio ** 2, 2 * zeta * ratio)
    assert vibration["transmissibility"] == pytest.approx(transmissibility, rel=1e-9)
    assert vibration["transmitted_force"] == pytest.approx(transmissibility * unbalance * omega ** 2, rel=1e-9)
    isolation = vibration["isolation"]
    support = mass * (omega / isolation["frequency_ratio"]) ** 2
    assert isolation["stiffness"] == pytest.approx(support, rel=1e-9)
    assert isolation["mount_stiffness"] == pytest.approx(support * shaft_stiffness / (shaft_stiffness - support),
                                                         rel=1e-9)
    base = machine["base_amplitude"]
    assert vibration["base_excitation"]["transmitted_force"] == pytest.approx(
        transmissibility * mass * omega ** 2 * base, rel=1e-9)
    assert vibration["combined"]["transmitted_force"] == pytest.approx(
        transmissibility * omega ** 2 * (unbalance + mass * base), rel=1e-9)

    scene, written = documented_runs["shaper"]
    dynamics = written["dynamics"]
    driving, resisting = np.array(dynamics["driving_moment"]), np.array(dynamics["resisting_moment"])
    scale = np.abs(dynamics["reduced_moment"]).max()
    assert np.allclose(driving + resisting, dynamics["reduced_moment"], rtol=0, atol=1e-11 * scale)
    work = np.array(dynamics["driving_work"]) - np.array(dynamics["resisting_work"])
    assert np.allclose(work, dynamics["kinetic_energy_change"], rtol=0, atol=1e-11 * np.abs(work).max())
    assert dynamics["delta_w_max"] == pytest.approx(np.ptp(dynamics["kinetic_energy_change"]), rel=1e-9)
    flywheel = dynamics["flywheel_inertia"]
    assert dynamics["kinetic_energy_start"] == pytest.approx(
        (dynamics["reduced_inertia"][0] + flywheel) * dynamics["omega"][0] ** 2 / 2, rel=1e-9)
    mean_rpm = dynamics["omega_mean"] * 30 / math.pi
    assert dynamics["flywheel_inertia_moved"] == pytest.approx(
        flywheel * (mean_rpm / dynamics["flywheel_shaft_rpm"]) ** 2, rel=1e-9)
    assert dynamics["omega_max"] - dynamics["omega_min"] == pytest.approx(
        dynamics["delta_reached"] * dynamics["omega_mean"], rel=1e-9)
    cycle = written["cycle_efficiency"]
    assert cycle["efficiency"] == pytest.approx(cycle["work_without_friction"] / cycle["work_with_friction"], rel=1e-9)
    assert cycle["friction_work"] == pytest.approx(cycle["work_with_friction"] - cycle["work_without_friction"],
                                                   rel=1e-9)
    for row in written["errors"]:
        if row["analytic"]:
            assert row["percent"] == pytest.approx((row["analytic"] - row["plan"]) / row["analytic"] * 100,
                                                   rel=1e-6, abs=1e-9)
    plans = tomllib.loads(scene.read_text(encoding="utf-8"))["positions"]["plans"]
    assert [p["index"] for p in written["positions"] if "forces" in p] == sorted(plans)
    for position in written["positions"]:
        if "forces" in position:
            forces = position["forces"]
            for table in (forces, forces["friction"]):
                assert table["lever_difference_percent"] == pytest.approx(
                    (table["lever_balancing_moment"] - table["balancing_moment"]) / table["balancing_moment"] * 100,
                    abs=1e-6)
            assert forces["friction"]["efficiency"] == pytest.approx(
                forces["balancing_moment"] / forces["friction"]["balancing_moment"], rel=1e-9)
            assert forces["polygon_scale"] == max(forces["polygon_scales"].values())


def test_a_scene_without_a_linkage_writes_the_results_its_row_says(documented_runs):
    """The results table said ``errors`` is always a list, as ``warnings`` is; a rotor's results.json has neither,
    nor any other key of the linkage: its row now says what the file holds."""
    row = next(line for line in EXTENSIONS.read_text(encoding="utf-8").splitlines()
               if line.startswith("| a scene with `[balancing]`, `[vibration]` or a `[dynamics]` load diagram"))
    holds, lacks = re.search(r"which then holds (.*?), none of the linkage's keys \((.*?)\)", row).groups()
    _, written = documented_runs["rotor"]
    assert set(written) <= set(re.findall(r"`(\w+)`", holds))
    assert {"graphplan", "versions", "scene", "balancing", "vibration"} <= set(written)
    assert not set(written) & set(re.findall(r"`(\w+)`", lacks))
    assert "always a list in a scene with a linkage" in results_row("errors")


def test_the_plots_the_readme_names_are_files_a_run_writes(documented_runs):
    """README named the plots ``balancing`` among them, a name a rotor's run writes no file of (its polygons are
    the drawing ``rotor_balancing``): each name it gives is a file of the runs that make it."""
    from fnmatch import fnmatch

    sentence = re.search(r"and the plots \((.*?)\) as PNG or PDF", README.read_text(encoding="utf-8"), re.DOTALL)[1]
    names = re.findall(r"`([\w*]+)`", sentence)
    assert {"motion", "balancing", "rotor_balancing"} <= set(names)
    files = {path.stem for scene, _ in documented_runs.values() for path in scene.parent.glob("*/*.svg")}
    # The accuracy report, the one output with run times of its own, is run by tests/test_accuracy_report.py.
    missing = [name for name in names if name != "accuracy" and not any(fnmatch(stem, name) for stem in files)]
    assert not missing
    assert "--figures" in sentence.split("`balancing`")[0]   # balancing.svg is the figures' plot


def test_every_warning_code_the_program_writes_is_a_documented_one():
    """The warnings' codes are the contract's way for a script to tell warnings apart: each code the source can
    write (a position's warning, a rotor's or a vibration's caution) has its row or its words in the results table,
    and each code documented there is one the source writes."""
    source = "\n".join(path.read_text(encoding="utf-8") for path in (ROOT / "graphplan").rglob("*.py"))
    written = set(re.findall(r'PositionWarning\(\s*[^,]+,\s*"([a-z-]+)"', source))
    written |= set(re.findall(r'^\s+code = "([a-z-]+)"$', source, flags=re.MULTILINE))
    extensions = EXTENSIONS.read_text(encoding="utf-8")
    documented = set(re.findall(r'^\| `warnings\[\]\.code = "([a-z-]+)"`', extensions, flags=re.MULTILINE))
    cautions = results_row("balancing.warnings[]") + results_row("vibration.warnings[]")
    documented |= set(re.findall(r'`code = "([a-z-]+)"`', cautions))
    assert len(written) > 20 and written == documented
