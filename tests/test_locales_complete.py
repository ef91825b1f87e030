"""A Russian or Chinese run reads in its own language from end to end: no English word in any text of any drawing
or plot it writes (the SVG's <text> and <tspan>, and matplotlib's, which draws its letters as paths and keeps the
text in a comment before each) nor in the note, the error tables or the force tables.

A run of three or more Latin letters shaped as a word (lower case, or one capital before lower case) is an English
word unless it is one of the texts every language writes alike (``ALIKE``: functions, Latin subscripts, matplotlib's
mathtext), the user's own text (the title, the ``[project]`` values) or a scene key (``rotor_inertia``,
``[measured] forces``), or a plan's letters named beside the mechanism's (``abe`` in "треугольник abe подобен
треугольнику ABE").  Symbols with a capital inside (lOA, VBA, Rij) are no word by that shape.  The runs: a fixture
with forces and the plot of its balancing load, the shaper's starter (dynamics, friction, the motion and its plot)
and the rotor's run near its resonance (balancing, vibration plots and the note's caution).
"""

from __future__ import annotations

import functools
import re
import tomllib
from pathlib import Path
from xml.etree import ElementTree

import pytest

from graphplan.cli import main

SVG = "{http://www.w3.org/2000/svg}"
FIXTURE = Path(__file__).parent.parent / "fixtures" / "ratchet_crank_rocker.toml"
# Written alike in every language: functions (Russian's arctg among them), Rij (the reaction of link i on link j;
# Rji, its opposite; Rijn, its normal component), the Latin subscripts of ωmax, Jrot, Mcl and the like, and the
# unit rad and r/min that Chinese texts write in Latin letters, as GB 3100 has them; and a name Chinese gives in
# Latin after its transcription, 克洛斯（Kloss）.
ALIKE = frozenset({"Rij", "Rji", "Rijn", "sin", "cos", "tan", "arctan", "arctg", "max", "min", "rot", "mot", "rad",
                   "Wmax", "Mmax", "Jrot", "Mcl", "Jcl", "mpmath", "Kloss"})
WORD = re.compile(r"(?<![A-Za-z0-9_])[A-Za-z_]{3,}(?![A-Za-z_])")
# matplotlib's mathtext ($\mathdefault{10^{-1}}$), the figures' file names and a scene table's key ([measured] forces).
NOT_PROSE = re.compile(r"\$[^$]*\$|[\w.-]+\.(?:svg|png|pdf|csv|md|json|tex|toml)\b|\[[\w.]+\]\s*\w+")


def svg_texts(path: Path) -> list[str]:
    root = ElementTree.parse(path).getroot()
    texts = ["".join(element.itertext()) for element in root.iter(SVG + "text")]
    return texts + re.findall(r"<!-- (.*?) -->", path.read_text(encoding="utf-8"))


def texts_of(folder: Path) -> list[tuple[str, str]]:
    """(file name, a line or a drawn text) of every drawing, plot and Markdown file the run wrote."""
    found = []
    for path in sorted(folder.rglob("*")):
        if path.suffix == ".svg":
            found += [(path.name, text) for text in svg_texts(path)]
        elif path.suffix == ".md":
            found += [(path.name, line) for line in path.read_text(encoding="utf-8").splitlines()]
    return found


def users_words(scene: Path) -> set[str]:
    """The words of the user's own texts: the title and [project], printed as typed in any language."""
    data = tomllib.loads(scene.read_text(encoding="utf-8"))
    texts = [data.get("scene", {}).get("title", "")] + [str(value) for value in data.get("project", {}).values()]
    return {word for text in texts for word in re.findall(r"[A-Za-z]+", text)}


def english_in(text: str, allowed: set[str]) -> set[str]:
    prose = NOT_PROSE.sub(" ", text)
    capitals = set(re.findall(r"[A-Z]+", prose))
    return {word for word in WORD.findall(prose)
            if re.fullmatch(r"[A-Z]?[a-z]+", word) and word not in ALIKE | allowed
            and not (word.islower() and word.upper() in capitals)}


def english_of_run(folder: Path, scene: Path) -> dict[str, set[str]]:
    """Each English word found, with the texts it was found in."""
    allowed, found = users_words(scene), {}
    for name, text in texts_of(folder):
        for word in english_in(text, allowed):
            found.setdefault(word, set()).add(f"{name}: {text[:120]}")
    return found


def _run(scene: Path, folder: Path, locale: str, *options: str) -> Path:
    assert main(["run", str(scene), "--locale", locale, "--out", str(folder), *options]) == 0
    return folder


def _starter(kind: str, locale: str, folder: Path) -> Path:
    scene = folder / f"{kind}_{locale}.toml"
    assert main(["new", kind, "--locale", locale, "--out", str(scene)]) == 0
    return scene


@functools.cache
def _fixture_run(locale: str, root: Path) -> Path:
    return _run(FIXTURE, root / f"ratchet_{locale}", locale, "--figures")


@pytest.fixture(scope="module")
def root(tmp_path_factory) -> Path:
    return tmp_path_factory.mktemp("locales")


@pytest.mark.parametrize("locale", ["ru", "zh"])
def test_a_fixture_with_forces_writes_no_english_word(root, locale):
    folder = _fixture_run(locale, root)
    assert (folder / "forces.md").exists() and (folder / "balancing.svg").exists()
    assert english_of_run(folder, FIXTURE) == {}


def test_the_rule_finds_the_english_of_an_english_run(root):
    """The same fixture in English: the rule that passes the Russian and Chinese runs finds English in it."""
    found = english_of_run(_fixture_run("en", root), FIXTURE)
    assert {"velocity", "acceleration", "position", "force"} <= {word.lower() for word in found}


@pytest.mark.parametrize("locale", ["ru", "zh"])
def test_the_shapers_starter_with_its_dynamics_and_friction_writes_no_english_word(root, locale):
    scene = _starter("shaper", locale, root)
    folder = _run(scene, root / f"shaper_{locale}", locale)
    assert (folder / "motion.svg").exists() and any(folder.glob("forces_friction_*.svg"))
    assert english_of_run(folder, scene) == {}


@pytest.mark.parametrize(("locale", "caution"), [("ru", "Внимание"), ("zh", "注意")])
def test_a_rotor_near_its_resonance_is_cautioned_of_it_in_its_own_language(root, locale, caution):
    """The rotor's starter at 302 rpm on mounts of ωn = √(1e5/100) = 31.62 rad/s (302.0 rpm), next to undamped."""
    scene = _starter("rotor", locale, root)
    text = scene.read_text(encoding="utf-8")
    text = re.sub(r"(?m)^rpm\s*=.*$", "rpm = 302.0", re.sub(r"(?m)^damping_ratio\s*=.*$", "damping_ratio = 0.001",
                                                             text))
    scene.write_text(text, encoding="utf-8")
    folder = _run(scene, root / f"rotor_{locale}", locale)
    note = (folder / "note.md").read_text(encoding="utf-8")
    assert any(line.startswith(caution) and "ζ = 0" in line for line in note.splitlines())
    assert any(folder.glob("vibration_*.svg")) and (folder / "rotor_balancing.svg").exists()
    assert english_of_run(folder, scene) == {}


def test_the_chinese_strings_keep_one_textbook_term_for_each_thing():
    """阻抗 is an electrical impedance: a resisting load, its work and moment are 阻力, 阻力功, 阻力矩; Kloss is
    克洛斯（Kloss）, not 克罗斯; Wittenbauer's curve is 能量–质量曲线 in every sentence (one note said 能量–质量图法)."""
    from graphplan.locale import strings

    text = "\n".join(strings("zh").values())
    assert "阻抗" not in text and "克罗斯" not in text and "能量–质量图法" not in text
    assert "阻力矩" in text and "阻力功" in text and "克洛斯（Kloss）公式" in text and "能量–质量曲线" in text
