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
