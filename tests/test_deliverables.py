"""What a run delivers: every piece the scene has data for by default, only those asked for, nothing it
cannot give; the command line's options; the starter scenes of ``graphplan new``."""

from __future__ import annotations

import re
import tomllib
import xml.etree.ElementTree as ElementTree
from pathlib import Path

import pytest
from test_scene_errors import to_toml

from graphplan.cli import Progress, main
from graphplan.starters import KINDS, starter

ROOT = Path(__file__).resolve().parent.parent
RATCHET = ROOT / "fixtures" / "ratchet_crank_rocker.toml"
NS = {"svg": "http://www.w3.org/2000/svg"}


def run(tmp_path: Path, *options: str, scene: Path = RATCHET) -> tuple[int, Path]:
    out = tmp_path / "out"
    return main(["run", str(scene), "--out", str(out), *options]), out


def names(folder: Path) -> set[str]:
    return {path.name for path in folder.iterdir()}


def layer_ids(svg: Path) -> set[str]:
    return {element.get("id") for element in ElementTree.parse(svg).getroot().iter() if element.get("id")}


def without_masses_and_loads(tmp_path: Path) -> Path:
    """The ratchet with its [links.N] tables and [[loads]] cut out: nothing for a force analysis."""
    document = tomllib.loads(RATCHET.read_text(encoding="utf-8"))
    del document["links"], document["loads"]
    path = tmp_path / "bare.toml"
    path.write_text(to_toml(document), encoding="utf-8")
    return path


def test_by_default_every_piece_the_scene_has_data_for(tmp_path):
    status, out = run(tmp_path)
    assert status == 0
    assert {"results.json", "positions.svg", "plan_5.svg", "plan_11.svg", "forces_5.svg", "forces_11.svg",
            "errors.md", "errors.csv", "forces.md"} <= names(out)
    # No figure without asking: matplotlib is not worth its second by default.
    assert "balancing.svg" not in names(out)


def test_no_force_pieces_without_masses_or_loads(tmp_path, capsys):
    scene = without_masses_and_loads(tmp_path)
    status, out = run(tmp_path, scene=scene)
    assert status == 0
    assert not {name for name in names(out) if name.startswith("forces")}
    assert {"plan_5.svg", "errors.md"} <= names(out)
    status, again = run(tmp_path / "asked", "--only", "positions,forces", scene=scene)
    assert status == 2 and not again.exists()
    assert "--only[1]: 'forces' needs masses or loads" in capsys.readouterr().err


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
    assert names(out) == {"results.json", "positions.svg", "errors.md", "errors.csv"}
    status, out = run(tmp_path / "only", "--only", "positions", scene=scene)
    assert names(out) == {"results.json", "positions.svg"}


def test_unknown_pieces_and_formats_are_refused_with_their_place(tmp_path, capsys):
    status, out = run(tmp_path, "--only", "velocity,plans")
    assert status == 2 and not out.exists()
    assert "--only[1]: must be one of positions, velocity" in capsys.readouterr().err
    status, out = run(tmp_path, "--format", "svg,jpg")
    assert status == 2 and not out.exists()
    assert "--format[1]: must be one of svg, png, pdf, dxf (got 'jpg')" in capsys.readouterr().err


def test_the_locale_option_turns_the_drawings_language(tmp_path):
    status, out = run(tmp_path, "--only", "velocity", "--locale", "zh")
    assert status == 0
    texts = " ".join(element.text or "" for element in ElementTree.parse(out / "plan_5.svg").getroot().iter())
    assert re.search(r"[\u4e00-\u9fff]", texts)


@pytest.mark.parametrize("kind", KINDS)
def test_each_starter_scene_checks_and_runs(tmp_path, kind, capsys):
    scene = tmp_path / f"{kind}.toml"
    assert main(["new", kind, "--out", str(scene)]) == 0
    assert scene.read_text(encoding="utf-8") == starter(kind)
    assert main(["check", str(scene)]) == 0
    assert "structure:" in capsys.readouterr().out
    status, out = run(tmp_path, scene=scene)
    assert status == 0
    assert {"results.json", "positions.svg", "errors.md"} <= names(out)
    assert any(name.startswith("forces_") for name in names(out))


def test_new_does_not_overwrite_a_scene(tmp_path, capsys):
    scene = tmp_path / "mine.toml"
    scene.write_text("# my own work\n", encoding="utf-8")
    assert main(["new", "crank-rocker", "--out", str(scene)]) == 2
    assert scene.read_text(encoding="utf-8") == "# my own work\n"
    assert "exists already" in capsys.readouterr().err


def test_a_progress_line_only_once_a_second_has_passed(capsys):
    Progress(after=3600.0).say("analysing")
    assert capsys.readouterr().err == ""
    Progress(after=-1.0).say("analysing")
    assert capsys.readouterr().err.startswith("graphplan: analysing (")
