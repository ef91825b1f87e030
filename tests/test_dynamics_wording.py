"""The dynamics part of the note and its drawing, worded and drawn as a teacher of the theory of machines would.

- A machine whose reduced moment of inertia does not vary (the flywheel starter, known by its load diagrams; a
  linkage whose crank alone has mass) has no term ½·Je′(φ)·ω² and no Je(φ): its equation of motion is
  J·dω/dt = Md − Mr, as the textbooks write it for a constant inertia, with Je's own value beside it.
- A crank's reduced load is a moment and a slider's a force: the Russian note called a crank's «момент (сила)».
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from graphplan.cli import main

ROOT = Path(__file__).resolve().parent.parent
RATCHET = ROOT / "fixtures" / "ratchet_crank_rocker.toml"
SLIDER = ROOT / "fixtures" / "slider_driven.toml"
NUMBER = r"(−?[\d.,]+)"
MOTOR = 'motor = { kind = "linear", stall_torque = 2000.0, no_load_rpm = 170.0 }\n'

# The textbook's symbols in each language: the machine's Je, the flywheel's, the rotor's through its gear, the
# driving and the resisting moments, and a kilogram-square-metre.
SYMBOLS = {
    "en": {"je": "Je", "flywheel": "JF", "rotor": "Jrot·u²", "md": "Md(ω)", "mr": "Mr(φ)", "unit": "kg·m²"},
    "ru": {"je": "Jп", "flywheel": "Jм", "rotor": "Jрот·u²", "md": "Mд(ω)", "mr": "Mс(φ)", "unit": "кг·м²"},
    "zh": {"je": "Je", "flywheel": "JF", "rotor": "Jrot·i²", "md": "Md(ω)", "mr": "Mr(φ)", "unit": "kg·m²"},
}


def value(text: str) -> float:
    return float(text.replace("−", "-").replace(",", "."))


def run_note(tmp_path: Path, text: str, pieces: str = "note,dynamics") -> str:
    scene = tmp_path / "scene.toml"
    scene.write_text(text, encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--only", pieces]) == 0
    return (out / "note.md").read_text(encoding="utf-8")


def starter(tmp_path: Path, locale: str) -> str:
    path = tmp_path / "flywheel.toml"
    assert main(["new", "flywheel", "--out", str(path), "--locale", locale]) == 0
    return path.read_text(encoding="utf-8")


def in_locale(text: str, locale: str) -> str:
    changed = re.sub(r'^locale\s*=\s*"\w+"', f'locale = "{locale}"', text, count=1, flags=re.MULTILINE)
    assert f'locale = "{locale}"' in changed
    return changed


def assert_constant_inertia_equation(note: str, locale: str, inertias: list[str], je: float) -> None:
    """The equation of motion J·dω/dt = Md − Mr with the inertias that turn with the shaft, and Je's value."""
    s = SYMBOLS[locale]
    terms = [s["je"], *inertias]
    inertia = terms[0] if len(terms) == 1 else "(" + " + ".join(terms) + ")"
    assert f"{inertia}·dω/dt = {s['md']} − {s['mr']}" in note
    # Nothing of a varying Je is left: no Je′(φ) term, no Je(φ).
    assert f"{s['je']}′(φ)" not in note and f"{s['je']}(φ)" not in note
    written = re.search(rf"{s['je']} = {NUMBER} {s['unit']}[^.;]*{s['je']}′ = 0", note)
    assert written, f"{s['je']}'s value beside the equation, constant"
    assert value(written.group(1)) == pytest.approx(je, rel=1e-4, abs=1e-12)


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_a_machine_known_by_its_load_diagrams_has_the_equation_of_a_constant_inertia(tmp_path, locale):
    """The flywheel starter, its own Je made 2.5 kg·m²: the note writes (Je + JF + Jrot·u²)·dω/dt = Md(ω) − Mr(φ),
    the flywheel sized and the rotor given in the scene, and Je = 2.5 kg·m² constant."""
    text = starter(tmp_path, locale)
    text, made = re.subn(r"^inertia\s*=\s*[\d.]+", "inertia = 2.5", text, count=1, flags=re.MULTILINE)
    assert made == 1
    assert re.search(r"rotor_inertia\s*=\s*0\.0*[1-9]", text), "the starter's motor has a rotor"
    note = run_note(tmp_path, text)
    s = SYMBOLS[locale]
    assert_constant_inertia_equation(note, locale, [s["flywheel"], s["rotor"]], 2.5)


def test_a_linkage_with_the_crank_alone_heavy_has_the_equation_of_a_constant_inertia(tmp_path):
    """The ratchet with its rocker's and its coupler's masses taken off: Je = m2·lOS2² = 16·0.08² kg·m² at every
    angle, so the equation is (Je + JF)·dω/dt = Md(ω) − Mr(φ); the motor's rotor is not given."""
    text = in_locale(RATCHET.read_text(encoding="utf-8"), "ru")
    text, taken = re.subn(r"\[links\.[34]\]\n(?:\w+\s*=.*\n)+", "", text)
    assert taken == 2
    text += "\n[dynamics]\ndelta = 0.05\n" + MOTOR
    note = run_note(tmp_path, text)
    assert_constant_inertia_equation(note, "ru", [SYMBOLS["ru"]["flywheel"]], 16.0 * 0.08 ** 2)


@pytest.mark.parametrize("locale", ["en", "ru"])
def test_a_varying_inertia_keeps_its_je_prime_term(tmp_path, locale):
    """The whole ratchet, its coupler and rocker heavy: Je varies, and the note keeps ½·Je′(φ)·ω²."""
    s = SYMBOLS[locale]
    text = in_locale(RATCHET.read_text(encoding="utf-8"), locale) + "\n[dynamics]\ndelta = 0.05\n" + MOTOR
    note = run_note(tmp_path, text)
    assert f"({s['je']}(φ) + {s['flywheel']})·dω/dt + ½·{s['je']}′(φ)·ω² = {s['md']} − {s['mr']}" in note


# What each language calls the reduced load of a crank (a moment) and of a slider (a force), and the words for the
# other kind, which its texts must not use.
MOMENT = {"en": "reduced moment", "ru": "приведённый момент", "zh": "等效力矩"}
FORCE = {"en": "reduced force", "ru": "приведённая сила", "zh": "等效力"}
NEITHER = {"en": ("reduced load", "moment (force)"), "ru": ("(сила)", "момент или сила"), "zh": ("等效载荷", "（力）")}


def plans_paragraph(note: str, symbol: str) -> str:
    """The paragraph after the dynamics table that says what its load column, headed ``symbol``, is."""
    paragraph = next((line for line in note.splitlines() if line.startswith(f"{symbol} ")), None)
    assert paragraph, f"the paragraph on {symbol}"
    return paragraph


def without_force_word(text: str, locale: str) -> str:
    """``text`` with its moment words taken out, so that a force word left is one (Chinese 等效力矩 holds 等效力)."""
    return text.replace(MOMENT[locale], "")


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_a_cranks_reduced_load_is_a_moment_in_the_table_and_its_paragraph(tmp_path, locale):
    """The ratchet (a crank, its driving moment taken constant): the table's load column is Mr, a moment read off
    the plans, and its title and paragraph say a moment, not a force or a load of no kind."""
    text = in_locale(RATCHET.read_text(encoding="utf-8"), locale) + "\n[dynamics]\ndelta = 0.05\n"
    note = run_note(tmp_path, text)
    symbol = {"en": "Mr", "ru": "Mс", "zh": "Mr"}[locale]
    paragraph = plans_paragraph(note, symbol)
    assert MOMENT[locale] in paragraph
    assert FORCE[locale] not in without_force_word(paragraph, locale)
    assert not any(word in paragraph for word in NEITHER[locale])
    lines = note.splitlines()
    header = next(at for at, line in enumerate(lines) if line.startswith("| ") and f"{symbol}, " in line)
    title = lines[header - 2]
    assert MOMENT[locale] in title.lower() and not any(word in title for word in NEITHER[locale]), title


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_a_sliders_reduced_load_is_a_force(tmp_path, locale):
    """The lever driven by a cylinder (a slider driver): its reduced load is a force, Fr, and its paragraph says so."""
    text = in_locale(SLIDER.read_text(encoding="utf-8"), locale) + "\n[dynamics]\n"
    note = run_note(tmp_path, text)
    symbol = {"en": "Fr", "ru": "Fс", "zh": "Fr"}[locale]
    paragraph = plans_paragraph(note, symbol)
    assert FORCE[locale] in paragraph and MOMENT[locale] not in paragraph
    assert not any(word in paragraph for word in NEITHER[locale])


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_every_cranks_plans_paragraph_and_table_title_name_a_moment_and_every_sliders_a_force(locale):
    """All three cases of the paragraph (the driving side constant, the resisting side, neither), not only the ones a
    scene above runs into: a crank's name a moment, a slider's a force, none both."""
    import tomllib

    text = tomllib.loads((ROOT / "graphplan" / "locales" / f"{locale}.toml").read_text(encoding="utf-8"))
    for side in ("driving", "resisting", "none"):
        crank, slider = text[f"note_dyn_plans_load_{side}"], text[f"note_dyn_plans_load_force_{side}"]
        assert MOMENT[locale] in crank and FORCE[locale] not in without_force_word(crank, locale), (side, crank)
        assert FORCE[locale] in slider and MOMENT[locale] not in slider, (side, slider)
        assert not any(word in crank + slider for word in NEITHER[locale]), side
    assert not any(word in text["note_dyn_table"] for word in NEITHER[locale])
    assert MOMENT[locale] in text["note_dyn_table"].lower()
