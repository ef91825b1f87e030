"""The scene format the project documents (docs/scene-format.md) is true of graphplan.

The page is the public contract of the scene and results files, kept in the repository word for word
as the design gives it, so that a reader of the project has it.  Its example scene runs, the results it
shows are the keys a run writes, and its Python example works as printed.
"""

from __future__ import annotations

import json
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


def test_the_example_scene_runs_and_writes_the_results_keys_the_page_shows(tmp_path, capsys):
    scene_text, = fenced("toml")
    loads(scene_text)   # every key of the example is one the reader accepts
    scene = tmp_path / "example.toml"
    scene.write_text(scene_text, encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "out"), "--only", "forces,errors"]) == 0
    written = json.loads((tmp_path / "out" / "results.json").read_text(encoding="utf-8"))
    shown = json.loads(fenced("json")[0])
    # The page's point "B", link "3" and reaction "R23" stand for every one: their names are the example's.
    def generic(document) -> set[str]:
        return {re.sub(r"\.(points|links|reactions)\.[^.]+", r".\1.*", path) for path in key_paths(document)}

    shown_paths, written_paths = generic(shown), generic(written)
    if not written["warnings"]:   # the example's scene runs without a warning: the list is empty
        shown_paths = {path for path in shown_paths if not path.startswith(".warnings[]")}
    assert shown_paths <= written_paths, sorted(shown_paths - written_paths)


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
    assert (tmp_path / "report" / "note.docx").exists()


def test_the_course_project_s_stall_warning_is_the_one_printed(tmp_path, capsys):
    from graphplan.starters import starter

    shown = re.search(r"^warning: dynamics: .*\(", COURSE.read_text(encoding="utf-8"), flags=re.MULTILINE)[0]
    scene = tmp_path / "weak.toml"
    scene.write_text(starter("shaper").replace("power = 3000.0", "power = 1500.0"), encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "out"), "--only", "dynamics"]) == 0
    assert shown in capsys.readouterr().out


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
