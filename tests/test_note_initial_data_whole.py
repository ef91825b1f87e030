"""A course project's note states the whole assignment under its initial data (исходные данные, 原始数据): the
links' masses, centres of mass and moments of inertia, the external loads and when they act, friction and the
dynamics' δ are given in section 2, not first met in the force analysis or the dynamics."""

from __future__ import annotations

import re
import tomllib
from collections.abc import Callable
from pathlib import Path

import pytest
from scene_texts import engine

from graphplan.cli import main

FIXTURES = Path(__file__).resolve().parent.parent / "fixtures"
MARK = {"en": ".", "ru": ","}


def _note(tmp_path: Path, scene: Path, locale: str) -> str:
    out = tmp_path / f"out-{locale}"
    assert main(["run", str(scene), "--out", str(out), "--only", "note", "--locale", locale]) == 0
    return (out / "note.md").read_text(encoding="utf-8")


@pytest.fixture(scope="module")
def note_of(tmp_path_factory) -> Callable[[Path, str], str]:
    """:func:`_note`, each scene's text in each language run once for the module (the shaper starter's note is read
    by two tests, a run of some three seconds each time)."""
    made: dict[tuple[str, str], str] = {}

    def note(scene: Path, locale: str) -> str:
        key = (scene.read_text(encoding="utf-8"), locale)
        if key not in made:
            made[key] = _note(tmp_path_factory.mktemp("note"), scene, locale)
        return made[key]

    return note


def _section(note: str, number: int) -> str:
    """The text of section ``number``, from its heading to the next of its level."""
    found = re.search(rf"^## {number}\.? .*?(?=^## )", note, re.DOTALL | re.MULTILINE)
    assert found, f"no section {number}"
    return found[0]


def _written(value: float, mark: str) -> str:
    """A value the scene gives as the note writes a number it is given: no trailing zeros, the locale's mark."""
    return f"{value:.10g}".replace(".", mark)


def _cells(section: str) -> list[list[str]]:
    return [[cell.strip() for cell in line.strip().strip("|").split("|")]
            for line in section.splitlines() if line.startswith("|") and not line.startswith("|--")]


def _shaper(tmp_path: Path) -> Path:
    scene = tmp_path / "shaper.toml"
    assert main(["new", "shaper", "--out", str(scene)]) == 0
    return scene


@pytest.mark.parametrize("locale", ("en", "ru"))
@pytest.mark.parametrize("scene_of", (_shaper, lambda tmp_path: FIXTURES / "shaper_six_bar.toml",
                                      lambda tmp_path: FIXTURES / "offset_slider_crank.toml"),
                         ids=("shaper starter", "shaper_six_bar", "offset_slider_crank"))
def test_every_mass_inertia_and_load_the_scene_gives_is_in_the_initial_data(tmp_path, capsys, locale, scene_of,
                                                                            note_of):
    scene = scene_of(tmp_path)
    given = tomllib.loads(scene.read_text(encoding="utf-8"))
    note = note_of(scene, locale)
    capsys.readouterr()
    mark = MARK[locale]
    data = _section(note, 2)
    cells = _cells(data)
    by_link = {row[0]: row for row in cells if len(row) == 4}
    for link, spec in given.get("links", {}).items():
        row = by_link[link]
        assert row[1] == (_written(spec["mass"], mark) if spec.get("mass") else "—"), row
        assert row[2] == spec.get("centre", "—"), row
        assert row[3] == (_written(spec["inertia"], mark) if spec.get("inertia") else "—"), row
    by_symbol = {row[1]: row[2] for row in cells if len(row) == 3}
    loads = given.get("loads", [])
    for load in loads:
        name = ("M" if load["kind"] == "moment" else "F") + str(load["link"])
        if sum(other["link"] == load["link"] for other in loads) > 1:
            continue  # F4.1, F4.2: named by their order, which the test of one load per link needs not repeat
        assert _written(abs(load["value"]), mark) in by_symbol[name].split(";")[0], (name, by_symbol)
        if isinstance(load.get("during"), dict):
            window = load["during"]
            assert _written(window["from"], mark) in by_symbol[name] and _written(window["to"], mark) in \
                by_symbol[name], (name, by_symbol[name])
    if any(spec.get("mass") for spec in given.get("links", {}).values()):
        assert by_symbol["g"].startswith(_written(given["scene"].get("gravity", 9.81), mark)), by_symbol
    for friction in given.get("friction", []):
        assert any(symbol.startswith("f") and value == _written(friction["f"], mark)
                   for symbol, value in by_symbol.items()), (friction, by_symbol)
    # Given before the force analysis works with them: section 2 comes before every other that names a mass.
    assert note.index(data) < min((note.index(line) for line in note.splitlines() if line.startswith("## 3")),
                                  default=len(note))


@pytest.mark.parametrize("locale", ("en", "ru"))
def test_the_dynamics_delta_is_in_the_initial_data(tmp_path, capsys, locale, note_of):
    scene = _shaper(tmp_path)
    delta = tomllib.loads(scene.read_text(encoding="utf-8"))["dynamics"]["delta"]
    note = note_of(scene, locale)
    capsys.readouterr()
    rows = {row[1]: row[2] for row in _cells(_section(note, 2)) if len(row) == 3}
    assert rows["δ"] == _written(delta, MARK[locale])


def _without(text: str, *headers: str) -> str:
    """The scene's text without the tables whose headers begin with ``headers``, each up to the next header."""
    blocks = re.split(r"(?m)^(?=\[)", text)
    return "".join(block for block in blocks if not block.startswith(headers))


def test_a_scene_without_masses_or_loads_gives_no_table_of_them(tmp_path, capsys):
    text = (FIXTURES / "offset_slider_crank.toml").read_text(encoding="utf-8")
    scene = tmp_path / "bare.toml"
    scene.write_text(_without(text, "[links", "[[loads", "[output"), encoding="utf-8")
    assert "mass" not in tomllib.loads(scene.read_text(encoding="utf-8")).get("links", {})
    note = _note(tmp_path, scene, "en")
    capsys.readouterr()
    data = _section(note, 2)
    # The dimensions' table alone: one caption, and no row of a mass, a load or g.
    assert len(re.findall(r"(?m)^Table \d+\.", data)) == 1, data
    assert "kg" not in data and "| g |" not in data


def test_a_load_of_its_own_stroke_is_told_along_that_stroke_not_the_working_one(tmp_path, capsys):
    """The engine's gas force on the piston's compression stroke is given along that stroke, which is not the
    working (expansion) stroke: its window must not read as a share of the working stroke."""
    scene = tmp_path / "engine.toml"
    scene.write_text(engine() + '[positions]\ncount = 12\nworking = { link = 4, sense = "backward" }\nplans = [2]\n',
                     encoding="utf-8")
    given = tomllib.loads(scene.read_text(encoding="utf-8"))["loads"]
    rows = {row[1]: row[2] for row in _cells(_section(_note(tmp_path, scene, "en"), 2)) if len(row) == 3}
    capsys.readouterr()
    for k, load in enumerate(given, start=1):
        told = rows[f"F4.{k}"]
        if load["stroke"]["sense"] == "backward":  # the working stroke's own sense
            assert "of the working stroke" in told, told
        else:
            assert "working stroke" not in told and f"link 4 moves {load['stroke']['sense']}" in told, told
