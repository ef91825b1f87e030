"""Force readings measured on the course sheet, which draws a force sheet's polygons larger than the record where it
has room (the ratchet's position 5: II(3,4) at 5 N/mm there, 10 in forces_5.svg and results.json), were told "drawn at
another μF, give `[drawing] force_scale = …`", which would redraw every polygon; they are now told which sheet they
fit, with the factor to the record's.

The sheet's μF of each polygon is read in the test off the caption under it in the sheet's SVG, and the readings are
the reactions of the linear system (not the polygons) over it.
"""

import dataclasses
import functools
import json
import re
from pathlib import Path

from sheet_texts import flat

import graphplan
from graphplan.analysis import analyse
from graphplan.misreadings import SheetPolygons, misread
from graphplan.report.note import note_markdown
from graphplan.report.tables import markdown
from graphplan.run import run

RATCHET = "fixtures/ratchet_crank_rocker.toml"
POSITION = 5
# The polygon each reading is read off: group II's polygon finds R23, R14 and R34 (drawn R43), the crank's R12.
POLYGON_OF = {"R23": "II(3,4)", "R14": "II(3,4)", "R34": "II(3,4)", "R12": "I(1,2)"}


def _scene(measured=None, locale="en"):
    scene = graphplan.load(RATCHET)
    return dataclasses.replace(scene, measured=measured or {}, locale=locale)


@functools.cache
def _drawn(folder: str):
    """The record's μF of each polygon (results.json) and, by the sheet's number, the μF its captions give them."""
    run(_scene(), Path(folder), only=["sheets"])
    record = next(position["forces"]["polygon_scales"] for position in
                  json.loads((Path(folder) / "results.json").read_text(encoding="utf-8"))["positions"]
                  if position["index"] == _index())
    captions = {}
    for path in Path(folder).glob("sheet_*.svg"):
        text = flat(path.read_text(encoding="utf-8"))
        for label in record:
            key = re.sub(r"[^A-Za-z0-9]+", "-", label).strip("-")
            at = text.find(f'id="forces-{POSITION}-polygon-{key}-caption"')
            if at >= 0:
                value = re.search(r"μF = ([0-9.]+) N/mm", text[at:]).group(1)
                captions[label] = (int(path.stem.removeprefix("sheet_")), float(value))
    return record, captions


@functools.cache
def _plain():
    return analyse(_scene())


def _index():
    return next(plan.index for plan in _plain().plans if plan.number == POSITION)


def _millimetres(scales):
    """Each reaction's length at its polygon's μF of ``scales``, from the linear system."""
    equilibrium = _plain().equilibrium
    return {name: round(abs(complex(equilibrium.reaction(name).force[_index()])) / scales[polygon], 2)
            for name, polygon in POLYGON_OF.items()}


def _far_off(warnings):
    return [line for line in warnings if "measured-far-off" in line or f"measured.{POSITION}:" in line]


def test_readings_of_the_course_sheets_larger_polygons_are_told_which_sheet_they_fit(tmp_path_factory):
    record, captions = _drawn(str(tmp_path_factory.mktemp("plain")))
    assert set(captions) == set(record)
    (sheet,) = {number for number, _ in captions.values()}
    drawn = {label: scale for label, (_, scale) in captions.items()}
    assert all(drawn[label] < record[label] for label in record)  # the course sheet draws them larger
    folder = tmp_path_factory.mktemp("read")
    done = run(_scene({POSITION: {"forces": _millimetres(drawn)}}), folder, only=["sheets", "errors", "note"])
    (warning,) = _far_off(done.warnings)
    sheet_scales = ", ".join(f"{label} {drawn[label]:g}" for label in record)
    record_scales = ", ".join(f"{label} {record[label]:g}" for label in record)
    assert (f"every reading of the force polygons fits the polygons of position {POSITION} on the course sheet "
            f"(sheet_{sheet}.svg, at μF = {sheet_scales} N/mm") in warning, warning
    assert f"not those of its force sheet (forces_{POSITION}.svg, at μF = {record_scales} N/mm)" in warning
    factors = {round(drawn[label] / record[label], 4) for label in record}
    (factor,) = factors  # each polygon the same standard steps larger here
    assert f"measure forces_{POSITION}.svg, or give these readings times {factor:g}" in warning
    assert "force_scale" not in warning and "misread" not in warning and "free-body" not in warning
    # results.json, errors.md and the note tell it as the console does.
    results = json.loads((folder / "results.json").read_text(encoding="utf-8"))
    assert [w["detail"] for w in results["warnings"] if w["code"] == "measured-far-off"] == [
        warning.split(": ", 1)[1]]
    # scene.results() lays the sheets out to tell it so: the analysis alone advises a force_scale.
    measured = _scene({POSITION: {"forces": _millimetres(drawn)}})
    assert measured.results(only=["sheets", "errors", "note"]) == results
    errors = (folder / "errors.md").read_text(encoding="utf-8")
    assert f"on the course sheet (sheet_{sheet}.svg, sheet {sheet}, at μF = {sheet_scales} N/mm" in errors
    note = (folder / "note.md").read_text(encoding="utf-8")
    (said,) = [line for line in note.splitlines() if "of the course project draws them" in line]
    assert ".svg" not in said and f"as sheet {sheet} of the course project" in said
    analysis = done.analysis
    russian = dataclasses.replace(analysis, scene=dataclasses.replace(analysis.scene, locale="ru"))
    assert f"согласуются с многоугольниками положения {POSITION} на листе курсового проекта" in markdown(russian)
    assert f"как их чертит лист {sheet} курсового проекта" in note_markdown(russian)
    chinese = dataclasses.replace(analysis, scene=dataclasses.replace(analysis.scene, locale="zh"))
    assert f"上第 {POSITION} 位置的力多边形相符" in markdown(chinese)
    # Following it: the readings times the factor are lengths on the record's polygons, and nothing is said.
    followed = {name: mm * drawn[POLYGON_OF[name]] / record[POLYGON_OF[name]]
                for name, mm in _millimetres(drawn).items()}
    assert not [w for w in analyse(_scene({POSITION: {"forces": followed}})).warnings
                if w.code == "measured-far-off"]


def test_readings_at_the_records_scale_are_told_nothing_of_the_course_sheet(tmp_path_factory):
    record, _ = _drawn(str(tmp_path_factory.mktemp("plain")))
    done = run(_scene({POSITION: {"forces": _millimetres(record)}}), tmp_path_factory.mktemp("record"),
               only=["sheets", "errors"])
    assert not _far_off(done.warnings)


def test_one_polygon_read_on_the_sheet_is_named_alone(tmp_path_factory):
    """Group II's polygon measured on the course sheet, the crank's R12 on the record's: II(3,4) alone is named."""
    record, captions = _drawn(str(tmp_path_factory.mktemp("plain")))
    drawn = {label: scale for label, (_, scale) in captions.items()}
    mixed = _millimetres({"II(3,4)": drawn["II(3,4)"], "I(1,2)": record["I(1,2)"]})
    done = run(_scene({POSITION: {"forces": mixed}}), tmp_path_factory.mktemp("mixed"), only=["sheets"])
    (warning,) = _far_off(done.warnings)
    assert (f"every reading of the force polygon II(3,4) fits the polygons of position {POSITION} on the course"
            in warning)
    assert f"at μF = {drawn['II(3,4)']:g} N/mm" in warning and "R12" not in warning


def test_without_the_sheets_drawn_the_advice_is_as_before():
    """The sheets' μF are known only once they are packed: a run without them says what it said."""
    record, drawn = {"II(3,4)": 10.0, "I(1,2)": 20.0}, {"II(3,4)": 5.0, "I(1,2)": 10.0}
    assert {plan.number: plan.forces.group_scales for plan in _plain().plans}[POSITION] == record
    analysis = analyse(_scene({POSITION: {"forces": _millimetres(drawn)}}))
    (warning,) = [w.detail for w in analysis.warnings if w.code == "measured-far-off"]
    assert "course sheet" not in warning and "force_scale = 5" in warning
    # Readings at a μF neither the sheet's nor the record's are advised the key, the sheet known or not.
    other = analyse(_scene({POSITION: {"forces": _millimetres({"II(3,4)": 2.5, "I(1,2)": 20.0})}}))
    drawn_plans = (*other.plans, *other.velocity_plans)
    (told,) = misread(other.mechanism, drawn_plans, {POSITION: (SheetPolygons(3, drawn),)})
    assert "course sheet" not in told.detail and "force_scale = 2.5" in told.detail
