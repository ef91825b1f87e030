"""The note's dynamics of a slider driver names what its model has: a reduced mass and a reduced force.

The table of the plan positions heads its columns me, kg and Fr, N, but the sentence under it told a student that
Fr was "Mr of the dynamics drawing", wrote "Fe = Md + Mr" where neither side was taken constant, and named "the
total Me"; the Russian caption called the columns a moment of inertia and a moment. The slider-driven lever
(fixtures/slider_driven.toml) is run with each side taken constant, in each language, and the crank's symbols,
taken from the locale's own strings, are looked for in the note's dynamics section.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from graphplan.cli import main
from graphplan.locale import strings

ROOT = Path(__file__).resolve().parent.parent
SLIDER = ROOT / "fixtures" / "slider_driven.toml"
# The cylinder's push along its axis: a driving load, so that the resisting side may be the one taken constant.
PUSH = '\n[[loads]]\nkind = "force"\nlink = 2\npoint = "A"\nvalue = 900.0\nangle = 0.0\nduring = "always"\n'
RESISTANCE = 'kind      = "moment"\nlink      = 4\nvalue     = 150.0        # N·m\nresisting = true\nduring    = "working"\n'
HEADINGS = {"en": "## 6. Dynamics of the machine", "ru": "## 6 Динамический анализ машины", "zh": "## 6 机器动力学"}


def _scene(constant: str, locale: str) -> str:
    text = SLIDER.read_text(encoding="utf-8").replace('locale  = "en"', f'locale  = "{locale}"')
    if constant in ("resisting", "none"):
        text += PUSH
    if constant == "resisting":  # no load is marked resisting: the 150 N·m goes, the push stays
        assert RESISTANCE in text
        text = text.replace("[[loads]]\n" + RESISTANCE, "")
    return text + f'\n[dynamics]\ncount = 12\nconstant = "{constant}"\n'


def _dynamics_section(tmp_path: Path, constant: str, locale: str) -> str:
    scene = tmp_path / "scene.toml"
    scene.write_text(_scene(constant, locale), encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--only", "dynamics,note"]) == 0
    note = (out / "note.md").read_text(encoding="utf-8")
    return note[note.index(HEADINGS[locale]):]


def _crank_symbols(text: dict[str, str]) -> set[str]:
    """Me, Mr, Md, MG in the locale's letters (Mп, Mс, Mд in Russian)."""
    found = {text["note_dyn_moment_symbol"], text["note_dyn_plans_symbol_driving"]}
    found |= {part.strip() for part in text["note_dyn_plans_symbol_resisting"].split("+")}
    return found


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
@pytest.mark.parametrize("constant", ["driving", "resisting", "none"])
def test_the_reduced_load_of_a_slider_is_a_force_in_the_note(tmp_path, constant, locale):
    section = _dynamics_section(tmp_path, constant, locale)
    text = strings(locale)
    for symbol in _crank_symbols(text):
        assert symbol not in section, symbol
    force = {"driving": text["note_dyn_plans_force_symbol_driving"],
             "resisting": text["note_dyn_plans_force_symbol_resisting"],
             "none": text["note_dyn_force_symbol"]}[constant]
    # The column the sentence explains is headed with the same symbol, in newtons (by plan: « (…)», «（…）»).
    assert f"| {force}, {text['newton']}{text['bracketed'].format(words=text['column_by_plan'])} |" in section
    assert text["note_dyn_table_slider"] in section and text["note_dyn_table"] not in section
    if constant == "none":
        assert {"en": "Fe = Fd + Fr", "ru": "Fп = Fд + Fс", "zh": "Fe = Fd + Fr"}[locale] in section
