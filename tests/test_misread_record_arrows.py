"""Force readings measured on the arrows of the groups cut free in the record's own force sheet, forces_N.svg, which
draws them beside its polygons at a μF of their own (the ratchet's crank at position 5: arrows at 100 N/mm, its polygon
at 20). Two readings or more of them were advised `[drawing] force_scale = 100`, which would redraw every polygon; they
are now told the arrows, their μF and the factor, by every run that draws the force sheets, course sheets or none.

The μF are read off the captions of forces_5.svg, the readings are the linear system's reactions over the arrows' μF,
and the test's ruler on the SVG's arrows gives the same lengths.
"""

import dataclasses
import json
import re
from pathlib import Path

import pytest
from drawn_lines import arrow_length, caption_text

from graphplan.analysis import analyse
from graphplan.run import run
from graphplan.scene import loads

RATCHET = "fixtures/ratchet_crank_rocker.toml"
# The crank cut free draws R32 and R12 whole, at their length (group II's reactions are drawn in components).
CRANK_ARROWS = ("R32", "R12")


def _scene(measured=None, locale="en"):
    text = re.sub(r"\[measured\.5\]\n.*\n.*\n", "", Path(RATCHET).read_text(encoding="utf-8"))
    scene = loads(text)
    return dataclasses.replace(scene, measured={number: {"forces": readings}
                                                for number, readings in (measured or {}).items()}, locale=locale)


@pytest.fixture(scope="module", autouse=True)
def _drawn(tmp_path_factory):
    """forces_5.svg as the run draws it, and the exact reactions of the crank at position 5."""
    folder = tmp_path_factory.mktemp("record")
    run(_scene(), folder, only=["forces"])
    _RECORD["svg"] = (folder / "forces_5.svg").read_text(encoding="utf-8")
    analysis = analyse(_scene())
    index = next(plan.index for plan in analysis.plans if plan.number == 5)
    _RECORD["exact"] = {name: abs(complex(analysis.equilibrium.reaction({"R32": "R23"}.get(name, name)).force[index]))
                        for name in CRANK_ARROWS}


_RECORD = {}


def _record():
    return _RECORD["svg"], _RECORD["exact"]


def _scales():
    svg, _ = _record()
    arrows = float(re.search(r"arrows: μF = ([0-9.]+) N/mm", caption_text(svg, "body-I-1-2")).group(1))
    polygon = float(re.search(r"μF = ([0-9.]+) N/mm", caption_text(svg, "polygon-I-1-2")).group(1))
    return arrows, polygon


def _far_off(warnings):
    return [line for line in warnings if "measured.5:" in line]


def test_the_crank_cut_free_draws_its_arrows_at_another_uf_than_its_polygon():
    arrows, polygon = _scales()
    assert arrows != polygon  # else no reading could tell the one from the other


def _arrow_readings():
    svg, exact = _record()
    arrows, _ = _scales()
    readings = {name: round(exact[name] / arrows, 2) for name in CRANK_ARROWS}
    for name in CRANK_ARROWS:
        # The ruler on forces_5.svg's arrow gives the same length.
        assert abs(arrow_length(svg, f"body-I-1-2-{name}") - readings[name]) < 0.05
    return readings


def test_readings_of_the_records_arrows_are_told_the_arrows_with_no_sheet_drawn(tmp_path):
    arrows, polygon = _scales()
    done = run(_scene({5: _arrow_readings()}), tmp_path, only=["forces", "errors", "note"])
    (warning,) = _far_off(done.warnings)
    assert ("every reading of the force polygon I(1,2) fits the arrows of the groups cut free of position 5 in "
            f"forces_5.svg at μF = {arrows:g} N/mm") in warning, warning
    assert f"not its polygons (at μF = {polygon:g} N/mm)" in warning
    assert f"give these readings times {arrows / polygon:.4g}" in warning and "force_scale" not in warning
    results = json.loads((tmp_path / "results.json").read_text(encoding="utf-8"))
    assert [w["detail"] for w in results["warnings"] if w["code"] == "measured-far-off"] == [warning.split(": ", 1)[1]]
    errors = (tmp_path / "errors.md").read_text(encoding="utf-8")
    assert (f"fits the arrows of the groups cut free of position 5 in forces_5.svg at μF = {arrows:g} N/mm"
            in errors)
    assert f"give these readings times {arrows / polygon:.4g}" in errors and "force_scale" not in errors
    (said,) = [line for line in (tmp_path / "note.md").read_text(encoding="utf-8").splitlines()
               if "as the force analysis draws them" in line]
    assert "fits the arrows of the groups cut free of position 5" in said and f"μF = {arrows:g} N/mm" in said
    assert ".svg" not in said


def test_every_locale_tells_the_arrows_in_its_words(tmp_path):
    arrows, polygon = _scales()
    for locale, words in (("ru", "стрелками сил на отсоединённых группах положения 5"),
                          ("zh", "第 5 位置各分离杆组上的力箭头")):
        folder = tmp_path / locale
        run(_scene({5: _arrow_readings()}, locale), folder, only=["forces", "errors"])
        errors = (folder / "errors.md").read_text(encoding="utf-8")
        line = next(line for line in errors.splitlines() if words in line)
        assert "forces_5.svg" in line and f"μF = {arrows:g}" in line and f"μF = {polygon:g}" in line
        assert f"{arrows / polygon:.4g}" in line and "force_scale" not in errors


def _told(scene, tmp_path, number=5):
    """The measured-far-off warnings of position ``number`` a run that draws the force sheets gives."""
    return [line for line in run(scene, tmp_path, only=["forces"]).warnings if f"measured.{number}:" in line]


def test_right_readings_are_not_told_and_a_wrong_force_scale_still_is(tmp_path):
    _, exact = _record()
    arrows, polygon = _scales()
    right = {name: round(exact[name] / polygon, 2) for name in CRANK_ARROWS}
    assert not _told(_scene({5: right}), tmp_path / "right")
    # Drawn at 50 N/mm, neither the polygon's μF nor the arrows': the key is told.
    other = 50.0
    assert other not in (arrows, polygon)
    wrong = {name: round(exact[name] / other, 2) for name in CRANK_ARROWS}
    (detail,) = _told(_scene({5: wrong}), tmp_path / "wrong")
    assert f"force_scale = {other:g}" in detail and "arrows of the groups cut free" not in detail


def test_readings_that_fit_arrows_drawn_at_one_newton_a_millimetre_are_still_told_typed_as_values(tmp_path):
    """The class III triad's crank at position 8 draws its arrows at 1 N/mm: readings there are the forces' values in
    N, told so as before (give the millimetres measured), not the arrows."""
    scene = dataclasses.replace(loads(Path("fixtures/triad_class_iii.toml").read_text(encoding="utf-8")), locale="en")
    analysis = analyse(scene)
    position = next(plan for plan in analysis.plans if plan.number == 8)
    from graphplan.render.drawings import force_sheet
    from graphplan.render.force_bodies import free_body_arrows

    assert free_body_arrows(force_sheet(analysis, position))["I(1,2)"][0] == 1.0
    values = {name: round(abs(complex(analysis.equilibrium.reaction({"R32": "R23"}.get(name, name))
                                      .force[position.index])), 2) for name in CRANK_ARROWS}
    (detail,) = _told(dataclasses.replace(scene, measured={**scene.measured, 8: {"forces": values}}), tmp_path, 8)
    assert "is the force it stands for, in N" in detail and "arrows of the groups cut free" not in detail
