"""Force readings measured on what else the course sheet draws larger than the record: the polygons of the force sheet
with friction (the ratchet's position 10 with a journal's friction at C: its sheet with friction at μF = 5 N/mm on a
sheet of its own, against 10 in forces_10.svg), and the arrows of the groups cut free (the ratchet's crank at position
5, its arrows at 100 N/mm on sheet 3, its polygon at 20 in forces_5.svg). Both were told "drawn at another μF, give
`[drawing] force_scale = …`", as the plain polygons were before they were known; they are now told which sheet and
which of its drawings they fit, with its μF and the factor to the record's polygons; the sheet with friction's with
no factor, only to measure forces_N.svg: its readings are reactions with friction, which times any factor are still
not the reactions without friction the error tables compare with.

Each μF is read in the test off the caption under its drawing in the sheet's SVG, and each reading is the reaction of
the linear system (with friction, for the sheet with friction) over it, as a hand measuring the sheet would give it.
"""

import dataclasses
import functools
import json
import re
from pathlib import Path

import pytest
from drawn_lines import arrow_length
from sheet_texts import flat

from graphplan.analysis import analyse
from graphplan.run import run
from graphplan.scene import loads

RATCHET = "fixtures/ratchet_crank_rocker.toml"
FRICTION_AT_C = '\n[[friction]]\njoint = "C"\nf = 0.15\nradius = 0.02\n'
# The polygon each reading is read off: group II's polygon finds R23, R14 and R34 (drawn R43), the crank's R12 and
# lays off R32.
POLYGON_OF = {"R23": "II(3,4)", "R14": "II(3,4)", "R43": "II(3,4)", "R12": "I(1,2)"}
# The crank cut free draws R32 and R12 whole (group II's reactions are drawn in components).
CRANK_ARROWS = ("R32", "R12")


def _scene(measured=None, friction=False):
    text = Path(RATCHET).read_text(encoding="utf-8")
    text = re.sub(r"\[measured\.5\]\n.*\n.*\n", "", text).replace("plans       = [5, 11]", "plans = [5, 10]")
    scene = loads(text + (FRICTION_AT_C if friction else ""))
    return dataclasses.replace(scene, measured=measured or {}, locale="en")


@functools.cache
def _plain(friction):
    return analyse(_scene(friction=friction))


def _index(friction, number):
    return next(plan.index for plan in _plain(friction).plans if plan.number == number)


def _sheets(folder, friction):
    """By each drawing's id on the course sheets, the sheet it stands on and the text of its caption."""
    run(_scene(friction=friction), folder, only=["sheets"])
    captions = {}
    for path in Path(folder).glob("sheet_*.svg"):
        text = flat(path.read_text(encoding="utf-8"))
        for found in re.finditer(r'id="([^"]+)-caption">(.*?)</g>', text):
            captions[found.group(1)] = (int(path.stem.removeprefix("sheet_")),
                                        " ".join(re.findall(r">([^<]*)</text>", found.group(2))))
    return captions


# With friction at C, the rows of position 5's and 10's sheets with friction apart beside the others save a sheet,
# drawn at the record's scales; the drawings read here, larger than the record, are those of the sheets whole.
pytestmark = pytest.mark.usefixtures("no_rows_apart")


@pytest.fixture(scope="module")
def friction_sheets(tmp_path_factory):
    return _sheets(tmp_path_factory.mktemp("friction"), True)


@pytest.fixture(scope="module")
def plain(tmp_path_factory):
    folder = tmp_path_factory.mktemp("plain")
    return folder, _sheets(folder, False)


def _scale_of(caption, word=""):
    return float(re.search(word + r"μF = ([0-9.]+) N/mm", caption).group(1))


def _record_scales(friction, number):
    plan = next(plan for plan in _plain(friction).plans if plan.number == number)
    return plan.forces.group_scales


def _far_off(warnings, number):
    return [line for line in warnings if f"measured.{number}:" in line]


def _exact(name, friction, number, with_friction):
    analysis = _plain(friction)
    equilibrium = analysis.with_friction if with_friction else analysis.equilibrium
    reaction = name if name in ("R23", "R14", "R12") else {"R43": "R34", "R32": "R23"}[name]
    return abs(complex(equilibrium.reaction(reaction).force[_index(friction, number)]))


def test_readings_of_the_sheet_with_frictions_larger_polygons_are_told_that_sheet(tmp_path_factory, friction_sheets):
    captions = friction_sheets
    sheet, _ = captions["forces-friction-10-polygon-II-3-4"]
    plain_sheet, _ = captions["forces-10-polygon-II-3-4"]
    assert sheet != plain_sheet  # the sheet with friction stands on a sheet of its own, which must be the one named
    drawn = {label: _scale_of(captions[f"forces-friction-10-polygon-{key}"][1])
             for label, key in (("II(3,4)", "II-3-4"), ("I(1,2)", "I-1-2"))}
    record = _record_scales(True, 10)
    assert all(drawn[label] < record[label] for label in record)  # the course sheet draws them larger
    # Lengths on the sheet with friction's polygons, as a ruler gives them.
    readings = {name: round(_exact(name, True, 10, True) / drawn[polygon], 2) for name, polygon in POLYGON_OF.items()}
    folder = tmp_path_factory.mktemp("read")
    done = run(_scene({10: {"forces": readings}}, friction=True), folder, only=["sheets", "errors", "note"])
    (warning,) = _far_off(done.warnings, 10)
    (sheet_scale,) = set(drawn.values())
    (record_scale,) = set(record.values())
    assert (f"every reading of the force polygons fits the polygons with friction of position 10 on the course sheet "
            f"(sheet_{sheet}.svg, at μF = {sheet_scale:g} N/mm") in warning, warning
    assert (f"not the polygons without friction of its force sheet (forces_10.svg, at μF = {record_scale:g} N/mm), "
            f"whose reactions they are checked against") in warning
    # Reactions with friction times a factor are still reactions with friction: no factor is given, no key.
    assert "measure the polygons of forces_10.svg" in warning
    assert "times" not in warning and "force_scale" not in warning
    results = json.loads((folder / "results.json").read_text(encoding="utf-8"))
    assert [w["detail"] for w in results["warnings"] if w["code"] == "measured-far-off"] == [
        warning.split(": ", 1)[1]]
    errors = (folder / "errors.md").read_text(encoding="utf-8")
    (line,) = [line for line in errors.splitlines() if "fits the polygons with friction of position 10" in line]
    assert (f"on the course sheet (sheet_{sheet}.svg, sheet {sheet}, at μF = {sheet_scale:g} N/mm; taken at it, every "
            f"reading is within") in line
    assert f"not the polygons without friction of its force sheet (forces_10.svg, at μF = {record_scale:g}" in line
    assert line.endswith("Measure the polygons of forces_10.svg.") and "times" not in line
    (said,) = [line for line in (folder / "note.md").read_text(encoding="utf-8").splitlines()
               if "of the course project draws them" in line]
    assert f"fits the polygons with friction of position 10 as sheet {sheet} of the course project" in said
    assert "readings of the reactions with friction" in said and "multiplied" not in said and ".svg" not in said
    ru = tmp_path_factory.mktemp("ru")
    run(dataclasses.replace(_scene({10: {"forces": readings}}, friction=True), locale="ru"), ru,
        only=["sheets", "errors", "note"])
    (line,) = [line for line in (ru / "errors.md").read_text(encoding="utf-8").splitlines()
               if "согласуются с многоугольниками положения 10 с учётом трения на листе" in line]
    assert f"лист {sheet}, μF = {sheet_scale:g} Н/мм" in line and "умножьте" not in line
    assert line.endswith("Измерьте многоугольники forces_10.svg.")
    (said,) = [line for line in (ru / "note.md").read_text(encoding="utf-8").splitlines()
               if "согласуются с многоугольниками положения 10 с учётом трения, как их чертит лист" in line]
    assert "умножить" not in said and "без учёта трения" in said and ".svg" not in said
    # Readings of the record's polygons, without friction or with, are right: nothing is said of them.
    for with_friction in (False, True):
        right = {name: round(_exact(name, True, 10, with_friction) / record[polygon], 2)
                 for name, polygon in POLYGON_OF.items()}
        assert not _far_off(run(_scene({10: {"forces": right}}, friction=True), tmp_path_factory.mktemp("right"),
                                only=["sheets"]).warnings, 10)


def test_readings_of_either_of_two_sheets_drawn_alike_are_told_the_one_they_were_read_off(tmp_path_factory,
                                                                                          friction_sheets):
    """At position 5 both force sheets, without friction and with, stand larger on sheets of their own at the same
    μF: readings of each are told the sheet whose reactions they are (the friction moves them by about 1 %)."""
    captions = friction_sheets
    for name, rubbing, words in (("forces-5", False, "the polygons of"),
                                 ("forces-friction-5", True, "the polygons with friction of")):
        sheet, _ = captions[f"{name}-polygon-II-3-4"]
        drawn = {label: _scale_of(captions[f"{name}-polygon-{key}"][1])
                 for label, key in (("II(3,4)", "II-3-4"), ("I(1,2)", "I-1-2"))}
        assert all(drawn[label] < scale for label, scale in _record_scales(True, 5).items())
        readings = {reading: round(_exact(reading, True, 5, rubbing) / drawn[polygon], 2)
                    for reading, polygon in POLYGON_OF.items()}
        done = run(_scene({5: {"forces": readings}}, friction=True), tmp_path_factory.mktemp("read"),
                   only=["sheets"])
        (warning,) = _far_off(done.warnings, 5)
        assert f"fits {words} position 5 on the course sheet (sheet_{sheet}.svg" in warning, warning


def test_readings_of_the_sheets_free_body_arrows_are_told_that_sheet(tmp_path_factory, plain):
    folder, captions = plain
    sheet, caption = captions["forces-5-body-I-1-2"]
    arrows = _scale_of(caption, "arrows: ")
    record = _record_scales(False, 5)["I(1,2)"]
    svg = (folder / f"sheet_{sheet}.svg").read_text(encoding="utf-8")
    readings = {}
    for name in CRANK_ARROWS:
        readings[name] = round(_exact(name, False, 5, False) / arrows, 2)
        # The ruler on the sheet's arrow gives the same length.
        assert abs(arrow_length(svg, f"forces-5-body-I-1-2-{name}") - readings[name]) < 0.05
    read = tmp_path_factory.mktemp("read")
    done = run(_scene({5: {"forces": readings}}), read, only=["sheets", "errors", "note"])
    (warning,) = _far_off(done.warnings, 5)
    assert (f"every reading of the force polygon I(1,2) fits the arrows of the groups cut free of position 5 on the "
            f"course sheet (sheet_{sheet}.svg, at μF = {arrows:g} N/mm") in warning, warning
    assert f"not the polygons of its force sheet (forces_5.svg, at μF = {record:g} N/mm)" in warning
    assert f"give these readings times {arrows / record:.4g}" in warning and "force_scale" not in warning
    # results.json and the note tell it as the console does, the note naming no file.
    results = json.loads((read / "results.json").read_text(encoding="utf-8"))
    assert [w["detail"] for w in results["warnings"] if w["code"] == "measured-far-off"] == [
        warning.split(": ", 1)[1]]
    (said,) = [line for line in (read / "note.md").read_text(encoding="utf-8").splitlines()
               if "of the course project draws them" in line]
    assert f"fits the arrows of the groups cut free of position 5 as sheet {sheet} of the course project" in said
    assert ".svg" not in said
    # Readings of the record's polygon are right: nothing is said.
    right = {name: round(_exact(name, False, 5, False) / record, 2) for name in CRANK_ARROWS}
    assert not _far_off(run(_scene({5: {"forces": right}}), tmp_path_factory.mktemp("right"),
                            only=["sheets"]).warnings, 5)


def test_readings_of_the_sheet_with_frictions_arrows_are_told_that_sheet_with_no_factor(tmp_path_factory,
                                                                                        friction_sheets):
    """The crank cut free as the sheet with friction draws it at position 10 (its arrows at their own μF, on a sheet
    of its own): told that sheet's arrows with friction and to measure forces_10.svg, with no factor, in English and
    in Russian (со стрелками)."""
    captions = friction_sheets
    sheet, caption = captions["forces-friction-10-body-I-1-2"]
    arrows = _scale_of(caption, "arrows: ")
    record = _record_scales(True, 10)["I(1,2)"]
    assert arrows != record
    readings = {name: round(_exact(name, True, 10, True) / arrows, 2) for name in CRANK_ARROWS}
    folder = tmp_path_factory.mktemp("arrows")
    done = run(_scene({10: {"forces": readings}}, friction=True), folder, only=["sheets", "errors", "note"])
    svg = (folder / f"sheet_{sheet}.svg").read_text(encoding="utf-8")
    for name in CRANK_ARROWS:
        assert abs(arrow_length(svg, f"forces-friction-10-body-I-1-2-{name}") - readings[name]) < 0.05
    (warning,) = _far_off(done.warnings, 10)
    assert (f"every reading of the force polygon I(1,2) fits the arrows of the groups cut free with friction of "
            f"position 10 on the course sheet (sheet_{sheet}.svg, at μF = {arrows:g} N/mm") in warning, warning
    assert f"not the polygons without friction of its force sheet (forces_10.svg, at μF = {record:g} N/mm)" in warning
    assert warning.endswith("measure the polygons of forces_10.svg")
    assert "times" not in warning and "force_scale" not in warning
    errors = (folder / "errors.md").read_text(encoding="utf-8")
    (line,) = [line for line in errors.splitlines() if "arrows of the groups cut free with friction" in line]
    assert f"(sheet_{sheet}.svg, sheet {sheet}, at μF = {arrows:g} N/mm" in line and "times" not in line
    (said,) = [line for line in (folder / "note.md").read_text(encoding="utf-8").splitlines()
               if "of the course project draws them" in line]
    assert "multiplied" not in said and "without friction" in said
    ru = tmp_path_factory.mktemp("ru")
    run(dataclasses.replace(_scene({10: {"forces": readings}}, friction=True), locale="ru"), ru,
        only=["sheets", "errors"])
    (line,) = [line for line in (ru / "errors.md").read_text(encoding="utf-8").splitlines()
               if "согласуются со стрелками сил на отсоединённых группах положения 10 с учётом трения на листе" in line]
    assert f"лист {sheet}, μF = {arrows:g} Н/мм" in line and "умножьте" not in line
