"""Runs made lighter for tests that read only part of what a run writes: the note's Markdown without its HTML and
LaTeX, a scene drawn on no sheet.  Each function says what was diffed to show the part a test reads unchanged."""

from __future__ import annotations

import contextlib
import re
from pathlib import Path

import pytest

FIXTURES_FOLDER = Path(__file__).resolve().parent.parent / "fixtures"


@contextlib.contextmanager
def notes_in_markdown_alone():
    """Runs that write their note.md and results.json as a full run does, and their note.html and note.tex empty.

    The HTML and the LaTeX are made from the finished note.md (deliverables.tables), so leaving them out changes
    no byte of what a test reads: diffed for every scene of test_teacher_review_structure's runs in en, ru and zh,
    note.md and results.json came out identical.  They were two thirds of a note's run (markdown-it and the LaTeX
    writer over the whole note), and the tests that read the note's Markdown read neither.
    """
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr("graphplan.report.note.note_html", lambda *args, **kwargs: "")
        patch.setattr("graphplan.report.latex.latex_document", lambda *args, **kwargs: "")
        yield


def on_no_sheet(path: Path, folder: Path) -> Path:
    """The scene at ``path`` drawn on no sheet ([drawing] sheet = "none"), written in ``folder``.

    The structure is the analysis's, made from [frame], [driver], [[groups]] and [points] before anything is drawn
    or any μl chosen; a sheet only makes `check` lay out the course sheets to refuse one that overflows, and makes a
    note whose scene gives no μl choose it by laying the sheets out at a few μl, once in each language: most of
    these runs' time.  Diffed for every scene of test_teacher_review_structure in en, ru and zh against the scene
    as written: the "structure:" and "W = " lines of `check`, results.json's structure, degrees_of_freedom and
    groups' kinds and links, the note's structural analysis and its group headings are the same (the Chinese
    notes, compared whole, were).
    """
    text = re.sub(r"^sheet *=.*\n", "", path.read_text(encoding="utf-8"), flags=re.MULTILINE)
    text, drawn = re.subn(r"^\[drawing\][^\n]*\n", '\\g<0>sheet = "none"\n', text, count=1, flags=re.MULTILINE)
    lighter = folder / path.name
    lighter.write_text(text if drawn else text + '\n[drawing]\nsheet = "none"\n', encoding="utf-8")
    return lighter


def plan_sheets_alone(scene: Path, folder: Path) -> list[Path]:
    """The plan sheets (plan_N.svg) of the scene at ``scene``, written in ``folder`` by a run of its velocity and
    acceleration plans alone: the mechanism and both plans of each plan position, as a full run draws them."""
    import graphplan
    from graphplan.run import run

    run(graphplan.load(scene), folder, only=["velocity", "acceleration"])
    plans = sorted(folder.glob("plan_*.svg"))
    assert plans, f"{scene.name}: the run wrote no plan"
    return plans



def plan_sheets_of(name: str, folder: Path) -> list[Path]:
    """:func:`plan_sheets_alone` of the fixture ``name`` (its file's stem, ``triad_class_iii``) or else of the starter
    of that kind (``slotted-lever``), written in ``folder``."""
    scene = FIXTURES_FOLDER / f"{name}.toml"
    if not scene.exists():
        from graphplan.starters import starter

        scene = folder / f"{name}.toml"
        scene.write_text(starter(name), encoding="utf-8")
    return plan_sheets_alone(scene, folder / "out")
