"""The dynamics part of the note and its drawing, worded and drawn as a teacher of the theory of machines would.

- A machine whose reduced moment of inertia does not vary (the flywheel starter, known by its load diagrams; a
  linkage whose crank alone has mass) has no term ½·Je′(φ)·ω² and no Je(φ): its equation of motion is
  J·dω/dt = Md − Mr, as the textbooks write it for a constant inertia, with Je's own value beside it.
- A crank's reduced load is a moment and a slider's a force: the Russian note called a crank's «момент (сила)».
- A diagram whose ordinate does not start at nought says so as a draftsman does: the slider-driven lever's me(s)
  ran from 6.5 kg at its abscissa with no mark; its abscissa is now nought and the ordinate broken by a zig-zag.
  Je(φ) is drawn from Je = 0, and stays so.
"""

from __future__ import annotations

import math
import re
from pathlib import Path
from xml.etree import ElementTree

import numpy as np
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


# What each language says where the machine's own Je is left out: "Je = 0 kg·m² is the machine's reduced moment of
# inertia" read as an inertia the machine has.
LEFT_OUT = {"en": "the machine's own reduced moment of inertia is left out of it",
            "ru": "собственный приведённый момент инерции машины в него не входит",
            "zh": "不计机器自身的等效转动惯量"}


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_a_machine_whose_own_inertia_the_scene_takes_as_zero_is_written_without_the_je_term(tmp_path, locale):
    """The flywheel starter as `graphplan new` writes it (inertia = 0.0): the equation is (JF + Jrot·u²)·dω/dt =
    Md(ω) − Mr(φ), and JF = ΔWmax/(ωm²·δ) with no "− Je" and no "− 0"; JF is the work over ωm²·δ, recomputed."""
    text = starter(tmp_path, locale)
    assert re.search(r"^inertia\s*=\s*0\.0\b", text, flags=re.MULTILINE), "the starter's machine has no Je"
    note = run_note(tmp_path, text)
    s = SYMBOLS[locale]
    assert f"({s['flywheel']} + {s['rotor']})·dω/dt = {s['md']} − {s['mr']}" in note
    assert LEFT_OUT[locale] in note and f"{s['je']} = 0 " not in note and f"{s['je']}′ = 0" not in note
    flywheel = re.search(rf"{s['flywheel']} = ΔW\w*/\(ω\w+²·δ\) = {NUMBER}/\({NUMBER}²·{NUMBER}\) = {NUMBER} {s['unit']}",
                         note.replace("ΔTнб", "ΔWнб"))
    assert flywheel, "JF = ΔWmax/(ωm²·δ) written out with its numbers"
    work, omega, delta, inertia = (value(group) for group in flywheel.groups())
    assert inertia == pytest.approx(work / (omega ** 2 * delta), rel=2e-4)
    drawn = "".join(ElementTree.parse(tmp_path / "out" / "dynamics.svg").getroot().itertext())
    assert f"δ) = {flywheel.group(4)} {s['unit']}" in drawn and f"δ) − {s['je']}" not in drawn, \
        "the drawing's JF without a Je of 0 subtracted, as the note"


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
    """The ratchet (a crank, its driving moment taken constant): the table's load column is −Mr, a moment read off
    the plans, and its title and paragraph say a moment, not a force or a load of no kind."""
    text = in_locale(RATCHET.read_text(encoding="utf-8"), locale) + "\n[dynamics]\ndelta = 0.05\n"
    note = run_note(tmp_path, text)
    # The loads' moment signed as their power: the resisting moment Mr with its sign turned.
    symbol = {"en": "−Mr", "ru": "−Mс", "zh": "−Mr"}[locale]
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
    """The lever driven by a cylinder (a slider driver): its reduced load is a force, −Fr, and its paragraph says so."""
    text = in_locale(SLIDER.read_text(encoding="utf-8"), locale) + "\n[dynamics]\n"
    note = run_note(tmp_path, text)
    symbol = {"en": "−Fr", "ru": "−Fс", "zh": "−Fr"}[locale]
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


SVG = "{http://www.w3.org/2000/svg}"


def drawing_group(out: Path, name: str) -> ElementTree.Element:
    root = ElementTree.parse(out / "dynamics.svg").getroot()
    return next(g for g in root.iter(f"{SVG}g") if g.get("id") == name)


def open_paths(group: ElementTree.Element) -> list[np.ndarray]:
    """The group's unfilled paths as (x, y) arrays in the SVG's mm, y down."""
    return [np.array([[float(v) for v in point.split(",")] for point in re.findall(r"[ML]([-\d.]+,[-\d.]+)", path.get("d"))])
            for path in group.iter(f"{SVG}path") if path.get("fill") == "none"]


def numbers_at(group: ElementTree.Element, anchor: str) -> list[tuple[float, float, float]]:
    """(value, x, y) of the group's texts set with ``anchor`` that are numbers alone."""
    found = []
    for text in group.iter(f"{SVG}text"):
        words = "".join(text.itertext())
        if text.get("text-anchor") == anchor and re.fullmatch(r"−?\d+(?:[.,]\d+)?", words):
            found.append((value(words), float(text.get("x")), float(text.get("y"))))
    return found


def lever_reduced_mass(s: float) -> float:
    """me(s) of the lever driven by a cylinder (fixtures/slider_driven.toml), from its own closure: the rod's end A at
    (s, 0), B on the circles AB = 0.225 m about A and CB = 0.15 m about C = (0.15, 0.25), right of A→C; the rod 6 kg
    at A, the coupler 1.4 kg at AB's middle with JS = 0.006, the lever 4 kg 0.06 m from C with JS = 0.02."""
    pivot = np.array([0.15, 0.25])

    def bodies(travel: float):
        a = np.array([travel, 0.0])
        towards = pivot - a
        distance = float(np.hypot(*towards))
        unit = towards / distance
        along = (0.225 ** 2 - 0.15 ** 2 + distance ** 2) / (2 * distance)
        b = a + along * unit - math.sqrt(0.225 ** 2 - along ** 2) * np.array([-unit[1], unit[0]])
        return a, (a + b) / 2, pivot + 0.4 * (b - pivot), math.atan2(*(b - a)[::-1]), math.atan2(*(b - pivot)[::-1])

    h = 1e-6
    ahead, behind = bodies(s + h), bodies(s - h)
    rates = [(np.asarray(p) - np.asarray(q)) / (2 * h) for p, q in zip(ahead, behind, strict=True)]
    return (6.0 * rates[0] @ rates[0] + 1.4 * rates[1] @ rates[1] + 0.006 * rates[3] ** 2
            + 4.0 * rates[2] @ rates[2] + 0.02 * rates[4] ** 2)


def test_the_sliders_reduced_mass_diagram_breaks_its_ordinate_over_an_abscissa_at_nought(tmp_path):
    """The lever's me(s) runs from 8.4 kg down to 6.9 kg (its own closure): its ordinate's ticks start at a round
    mass under that, and the abscissa, where they would read 6.5 kg, stood unmarked.  The abscissa is numbered 0 on
    the ordinate, a zig-zag crosses the ordinate between it and the lowest mass, and the curve stands at its masses
    on the numbers above the break."""
    text = SLIDER.read_text(encoding="utf-8") + "\n[dynamics]\n"
    run_note(tmp_path, text)
    group = drawing_group(tmp_path / "out", "inertia")
    masses = sorted(numbers_at(group, "end"), key=lambda tick: -tick[2])   # the ordinate's, from the bottom up
    assert len(masses) >= 3
    curve = max(open_paths(group), key=len)
    ordinate = float(curve[0, 0])   # the curve starts at s = 0
    axis = max((path for path in open_paths(group) if len(path) == 2 and abs(path[0, 1] - path[1, 1]) < 1e-9),
               key=lambda path: abs(path[1, 0] - path[0, 0]))
    abscissa = float(axis[0, 1])
    # Each number beside its tick, a short stroke left of the ordinate, from the bottom up.
    ticks = sorted((float(path[0, 1]) for path in open_paths(group) if len(path) == 2
                    and abs(path[0, 1] - path[1, 1]) < 1e-9 and abs(path[1, 0] - ordinate) < 1e-6
                    and 0.5 < path[1, 0] - path[0, 0] < 2.0), reverse=True)
    assert len(ticks) == len(masses) and all(abs(tick - y) < 2.0 for tick, (_, _, y) in zip(ticks, masses))
    # The number at the abscissa says what the abscissa is: nought.
    assert masses[0][0] == 0.0 and ticks[0] == pytest.approx(abscissa, abs=1e-6), masses
    resumed = [(mass, tick) for (mass, _, _), tick in zip(masses[1:], ticks[1:])]
    slope, intercept = np.polyfit([tick for _, tick in resumed], [mass for mass, _ in resumed], 1)
    low, high = lever_reduced_mass(0.2), lever_reduced_mass(0.0)
    assert slope * abscissa + intercept > 0.5 * low, "the numbers above resume far from nought"
    # So the axis is broken: a zig-zag across the ordinate, between the abscissa and the lowest mass numbered.
    lowest_numbered = resumed[0][1]
    zigzags = [path for path in open_paths(group) if len(path) >= 4
               and np.all(np.abs(path[:, 0] - ordinate) < 3.0)
               and np.min(path[:, 0]) < ordinate - 0.5 and np.max(path[:, 0]) > ordinate + 0.5
               and lowest_numbered < np.min(path[:, 1]) and np.max(path[:, 1]) < abscissa]
    assert zigzags, "a break mark across the ordinate"
    # The curve stands at the lever's own masses on the numbers above the break.
    assert slope * float(curve[0, 1]) + intercept == pytest.approx(high, rel=5e-3)
    assert slope * float(curve[-1, 1]) + intercept == pytest.approx(low, rel=5e-3)


def test_je_of_phi_is_drawn_from_je_at_nought(tmp_path):
    """The ratchet's Je(φ), turned under its energy–mass diagram: the numbers of its Je axis, read as a straight
    scale, give nought at the φ axis it starts from, so that it needs no break."""
    text = RATCHET.read_text(encoding="utf-8") + "\n[dynamics]\ndelta = 0.05\n"
    run_note(tmp_path, text)
    group = drawing_group(tmp_path / "out", "inertia")
    inertias = numbers_at(group, "middle")
    assert len(inertias) >= 2
    slope, intercept = np.polyfit([x for _, x, _ in inertias], [v for v, _, _ in inertias], 1)
    angles = numbers_at(group, "end")
    phi_axis = float(np.median([x for _, x, _ in angles])) + 1.0 + 1.2   # the φ numbers end a tick and 1 mm short
    assert slope * phi_axis + intercept == pytest.approx(0.0, abs=1e-3 * max(v for v, _, _ in inertias))
