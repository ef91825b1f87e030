"""The note tells where a course sheet draws a position's Zhukovsky's lever at another μV than its table's.

The note works each lever (its table of arms h and moments, Fb from ΣMp = 0) at the μV of forces_N.svg, the figure it
shows, which is laid out alone whatever the sheet format; a small course sheet (sheet_K.svg, what a student hands in)
draws its own copy of the lever coarser, to fit.  Measured there, the arms are the table's times the ratio of the two
μV: the sentence after the table names that sheet, its μV and the factor.  Read back off the drawings as written: the
μV each lever's caption gives on forces_N.svg (forces_friction_N.svg) and on the course sheet that holds it, and the
arm h1 drawn on that sheet, against the note's sentence and table.
"""

from __future__ import annotations

import re
from pathlib import Path
from xml.etree import ElementTree

import pytest
from lever_arms import SVG, note_arms, sheet_arms

from graphplan.cli import main
from graphplan.locale import strings
from graphplan.render.primitives import svg_id
from graphplan.starters import starter

# The slider-crank starter with friction in its slider's guide and its crank's journal: the lever with friction on
# forces_friction_2.svg beside the plain one on forces_2.svg; its force sheets of position 2 alone keep a run to a
# few seconds.
FRICTION = """
[[friction]]
joint = "B"
links = [4, 1]
f     = 0.1

[[friction]]
joint  = "O"
f      = 0.08
radius = 0.02

"""
# A lever's caption on a course sheet, under the name of the drawing it stands in there (forces-2-3, the third part of
# position 2's force sheet; forces-friction-8): the position and whether it is the lever with friction.
SHEET_CAPTION = re.compile(r"(?P<panel>forces-(?P<friction>friction-)?(?P<number>\d+)(?:-[^\s\"]*)?)-lever-caption")
SCALE = re.compile(r"μV = (?P<value>\d+(?:[.,]\d+)?)")
# The arms the note writes to 0.01 mm, times a factor below 1 (the sheet's copy is coarser): 0.005 mm; the factor to
# four significant digits, a relative 1e-4 at most of arms under 250 mm: 0.025 mm; the sheet's coordinates to
# 0.001 mm.  0.05 mm is above their sum and a tenth of the starter's drafting precision (0.5 mm).
ARM_TOLERANCE_MM = 0.05


def scene_file(tmp_path: Path, locale: str) -> Path:
    path = tmp_path / "slider_crank.toml"
    document = starter("slider-crank", locale).replace("[positions]", FRICTION + "[positions]", 1)
    path.write_text(re.sub(r"^plans\s*=.*$", "plans = [2]", document, count=1, flags=re.MULTILINE), encoding="utf-8")
    return path


def texts(layer) -> str:
    return " ".join("".join(text.itertext()) for text in layer.iter(f"{SVG}text"))


def caption_scale(caption: str) -> str:
    """μV as the lever's caption writes it (``0.07854``, in Russian ``0,07854``)."""
    found = SCALE.search(caption)
    assert found, f"no μV in the lever's caption: {caption}"
    return found["value"]


def levers_alone(out: Path) -> dict[tuple[int, bool], str]:
    """μV of each lever on forces_N.svg and forces_friction_N.svg, by its position and whether it has friction."""
    found = {}
    for path in out.glob("forces_*.svg"):
        named = re.fullmatch(r"forces_(friction_)?(\d+)\.svg", path.name)
        if named:
            layers = {layer.get("id"): layer for layer in ElementTree.parse(path).getroot().iter(f"{SVG}g")}
            found[int(named[2]), bool(named[1])] = caption_scale(texts(layers["lever-caption"]))
    return found


def levers_on_sheets(out: Path) -> dict[tuple[int, bool], tuple[int, str, str]]:
    """Each lever a course sheet draws, by its position and whether it has friction: the sheet's number, its μV there
    and the name of the drawing that holds it (which starts its layers' ids)."""
    found = {}
    for path in out.glob("sheet_*.svg"):
        sheet = int(path.stem.removeprefix("sheet_"))
        for layer in ElementTree.parse(path).getroot().iter(f"{SVG}g"):
            lever = SHEET_CAPTION.fullmatch(layer.get("id") or "")
            if lever:
                key = int(lever["number"]), bool(lever["friction"])
                assert key not in found, f"two course sheets draw the lever of {key}"
                found[key] = sheet, caption_scale(texts(layer)), lever["panel"]
    return found


def as_number(written: str) -> float:
    return float(written.replace(",", "."))


def sentence_pattern(locale: str) -> re.Pattern:
    """The note's sentence with its values as groups."""
    groups = {"sheet": r"(?P<sheet>\d+)", "scale": "(?P<scale>.+?)", "ratio": r"(?P<ratio>\S+)",
              "factor": r"(?P<factor>\d+(?:[.,]\d+)?)"}
    parts = re.split(r"\{(\w+)\}", strings(locale)["note_lever_on_sheet"])
    return re.compile("".join(groups[part] if k % 2 else re.escape(part) for k, part in enumerate(parts)))


def after_table(note: str, caption: str) -> str:
    """The paragraph right after the table captioned ``caption``."""
    lines = note.splitlines()
    start = next(k for k, line in enumerate(lines) if line.endswith(caption))
    end = next(k for k in range(start + 1, len(lines)) if lines[k - 1].startswith("|") and not lines[k].startswith("|"))
    return next(line for line in lines[end:] if line.strip())


def run(tmp_path: Path, locale: str, *options: str) -> Path:
    out = tmp_path / "out"
    assert main(["run", str(scene_file(tmp_path, locale)), "--out", str(out), *options]) == 0
    return out


# The levers (position, with friction) a course sheet of the format draws at another μV than forces_N.svg's: how
# the sheets come out, which the test checks only so that both kinds of lever are read.
@pytest.mark.parametrize(("locale", "sheet", "coarser"), [
    ("en", "A4", {(2, False), (2, True)}),  # both drawn at the velocity plan's 0.07854 instead of 0.04
    ("ru", "A2", {(2, True)}),  # the lever with friction a step coarser (0.05), the plain one as forces_2.svg's
    ("zh", "A2", {(2, False), (2, True)}),  # the Chinese lettering's wider captions: both a step coarser
])
def test_the_note_tells_the_course_sheet_that_draws_a_lever_at_another_scale(tmp_path, locale, sheet, coarser):
    out = run(tmp_path, locale, "--sheet", sheet, "--only", "lever,note,sheets")
    note = (out / "note.md").read_text(encoding="utf-8")
    text = strings(locale)
    sentence = sentence_pattern(locale)
    alone, drawn = levers_alone(out), levers_on_sheets(out)
    assert set(alone) == set(drawn) == {(2, False), (2, True)}
    for (number, friction), (sheet_number, there, panel) in drawn.items():
        worked = alone[number, friction]
        table = "note_friction_lever_table" if friction else "note_lever_table"
        told = sentence.fullmatch(after_table(note, text[table].format(number=number)))
        differ = (number, friction) in coarser
        assert (there != worked) == differ, f"position {number}: μV {worked} alone, {there} on sheet {sheet_number}"
        if not differ:
            assert told is None, f"position {number}: {told and told[0]}"
            continue
        assert told, f"position {number}{' with friction' if friction else ''}: no sentence after its lever's table"
        factor = as_number(worked) / as_number(there)
        assert int(told["sheet"]) == sheet_number
        assert told["scale"] == text["velocity_scale"].format(value=there)
        assert told["ratio"] == f"{worked}/{there}"
        assert as_number(told["factor"]) == pytest.approx(factor, rel=1e-3)
        if locale == "en":  # the layers' ids name the loads in Latin letters, as English does (Fu3, not Fи3)
            # The arm h1 measured on the course sheet is the table's times the factor the sentence gives.
            named, _, lengths = sheet_arms(out / f"sheet_{sheet_number}.svg", panel)
            load = next(load for load, arm in named.items() if arm == "h1")
            (written,) = [length for name, arm, length in note_arms(note, locale, table)[number] if name == load]
            assert lengths[svg_id("lever-arm", load)] == pytest.approx(written * as_number(told["factor"]),
                                                                       abs=ARM_TOLERANCE_MM)
    assert len(sentence.findall(note)) == len(coarser)


def test_without_the_course_sheets_the_note_tells_of_none(tmp_path):
    """A4 draws every lever coarser on its sheets; a run that draws no sheets has none to tell of."""
    out = run(tmp_path, "en", "--sheet", "A4", "--only", "lever,note")
    assert not list(out.glob("sheet_*.svg"))
    assert not sentence_pattern("en").search((out / "note.md").read_text(encoding="utf-8"))
