"""The loads the force analysis adds are named in Latin inside (Fu3, Mu3, hu3, Mb, Fb) and so in results.json and
errors.csv, but a Russian reader's textbook writes them Fи3, Mи3, hи3, Mу, Fу: the Russian sheets and texts mixed
Fu3 and Mb with the Cyrillic indices they write elsewhere (Fд, Mс, Aс).  Each is shown as its locale writes it."""

from __future__ import annotations

import csv
import json
import re
from pathlib import Path

import pytest
from sheet_texts import flat

from graphplan.cli import main
from graphplan.locale import load_symbol, load_symbols_in, strings

# A Latin name of an added load as a word of its own: Fu3, Mu3′, hu3, Mb, Mb0, Fb, hb (not Mf23, F4, M4.1).
LATIN = re.compile(r"(?<![^\W_])(?:(?:Fu|Mu|hu)\d|(?:Mb|Fb|hb)(?:0|′|″)?(?![^\W_]))")


def test_each_added_load_is_named_as_its_locale_writes_it_and_no_other_name_changes():
    russian = strings("ru")
    assert [load_symbol(name, russian) for name in ("Fu3", "Mu4″", "hu3", "Mb", "Mb0", "Fb", "hb", "Fu5·x")] == [
        "Fи3", "Mи4″", "hи3", "Mу", "Mу0", "Fу", "hу", "Fи5·x"]
    # The scene's own loads, the friction loads, the weights and the reactions keep their names in every locale.
    for name in ("F4", "M4.1", "Mf23", "Ff16", "G3", "R23τ", "Mc"):
        assert load_symbol(name, russian) == name
    for locale in ("en", "zh"):
        assert load_symbol("Fu3", strings(locale)) == "Fu3" and load_symbol("Mb", strings(locale)) == "Mb"
    assert load_symbols_in("ΣF2 + Fb + R12 = 0; Mb0/Mb; M(Fu3)", russian) == "ΣF2 + Fу + R12 = 0; Mу0/Mу; M(Fи3)"


def _svg_words(path: Path) -> str:
    """The words an SVG draws, not its ids, which keep the internal names: each text's words whole, its indices'
    runs joined."""
    return "\n".join(re.findall(r">([^<>]+)<", flat(path.read_text(encoding="utf-8"))))


def _run(folder: Path, locale: str) -> Path:
    scene = folder / "crank-rocker.toml"
    assert main(["new", "crank-rocker", "--locale", locale, "--out", str(scene)]) == 0
    # The balancing moment read by hand, that errors.md names it beside errors.csv's key.
    scene.write_text(scene.read_text(encoding="utf-8") + "\n[measured.5]\nbalancing = 640.0\n", encoding="utf-8")
    out = folder / "out"
    assert main(["run", str(scene), "--out", str(out)]) == 0
    return out


@pytest.fixture(scope="module")
def russian(tmp_path_factory) -> Path:
    return _run(tmp_path_factory.mktemp("ru"), "ru")


@pytest.fixture(scope="module")
def english(tmp_path_factory) -> Path:
    return _run(tmp_path_factory.mktemp("en"), "en")


def _read(out: Path) -> dict[str, str]:
    texts = {path.name: _svg_words(path) for path in sorted(out.glob("*.svg"))
             if path.name.startswith(("sheet_", "forces_"))}
    texts.update({name: (out / name).read_text(encoding="utf-8") for name in ("forces.md", "note.md", "errors.md")})
    return texts


def test_a_russian_run_draws_and_writes_f_i_m_i_and_m_u_and_no_latin_name_of_them(russian):
    texts = _read(russian)
    sheets = [name for name in texts if name.startswith("sheet_")]
    force_sheets = [name for name in sheets if "Fи3" in texts[name]]
    assert force_sheets, "no course sheet draws the inertia force Fи3"
    for name in [*force_sheets, "forces_5.svg", "forces.md", "note.md"]:
        assert all(symbol in texts[name] for symbol in ("Fи3", "Mи3", "Mу")), name
    assert "ΣMp:" in texts["forces_5.svg"] and "·hу = 0" in texts["forces_5.svg"]  # the lever's Fу·hу
    assert "| Mу | Н·м |" in texts["errors.md"]
    for name, text in texts.items():
        assert not LATIN.search(text), (name, LATIN.search(text)[0])


def test_a_russian_run_keeps_the_internal_names_in_results_json_and_errors_csv(russian):
    results = (russian / "results.json").read_text(encoding="utf-8")
    forces = next(position["forces"] for position in json.loads(results)["positions"] if "forces" in position)
    assert {"balancing_moment", "lever_balancing_moment", "reactions"} <= forces.keys()
    assert not re.search("[FMh][иу]", results)
    with (russian / "errors.csv").open(encoding="utf-8") as rows:
        quantities = {row["quantity"] for row in csv.DictReader(rows)}
    assert "Mb" in quantities and "Mу" not in quantities


def test_an_english_run_still_names_fu_mu_and_mb(english):
    texts = _read(english)
    for name in ["forces_5.svg", "forces.md", "note.md"]:
        assert all(symbol in texts[name] for symbol in ("Fu3", "Mu3", "Mb")), name
    assert "| Mb | N·m |" in texts["errors.md"]
    assert not any(re.search("[FMh][иу]", text) for text in texts.values())
