"""Force readings measured on the record's own polygons with friction, forces_friction_N.svg (the shaper starter with
the ram's slide at f = 0.3: at position 10 the friction lengthens R45, R56, R23, R14, R43 and R12 by 25 to 42 %, all
polygons at the μF of forces_10.svg). They were compared with the reactions without friction and advised
`[drawing] force_scale = 15.2` for group II(3,4), the rest named misread; they are now told the polygons with friction,
in forces_friction_10.svg at its μF, and to measure forces_10.svg: no factor turns reactions with friction into those
without.

The μF are read off forces_friction_10.svg's captions; each reading is the reaction with friction of the linear system
(statics, not the polygons) over its polygon's μF, as a hand measuring the drawing would give it.
"""

import dataclasses
import functools
import json
import re

import pytest
from drawn_lines import caption_text

from graphplan.analysis import analyse
from graphplan.run import run
from graphplan.scene import loads
from graphplan.starters import starter

NUMBER = 10
# The group whose polygon finds each reaction (R43 is drawn as found, read at its polygon's μF).
POLYGON_OF = {"R45": "II-5-6", "R56": "II-5-6", "R16": "II-5-6", "R23": "II-3-4", "R14": "II-3-4", "R43": "II-3-4",
              "R12": "I-1-2"}


def _scene(readings=None, locale="en"):
    text = starter("shaper")
    assert "f     = 0.1\n" in text  # the ram's slide
    scene = loads(text.replace("f     = 0.1\n", "f     = 0.3\n"))
    measured = {NUMBER: {"forces": readings}} if readings else {}
    # On no sheet: μl is then not chosen by laying out the course sheets, four fifths of each run here, and no run
    # here draws them; the forces, errors and note files of the run are the same bytes either way (diffed once).
    drawing = dataclasses.replace(scene.drawing, sheet="none")
    return dataclasses.replace(scene, measured=measured, locale=locale, drawing=drawing)


@functools.cache
def _exact():
    """By reading, the reaction (N) of the linear system without friction and with, at position 10."""
    analysis = analyse(_scene())
    index = next(plan.index for plan in analysis.plans if plan.number == NUMBER)
    return {name: (abs(complex(analysis.equilibrium.reaction(name).force[index])),
                   abs(complex(analysis.with_friction.reaction(name).force[index]))) for name in POLYGON_OF}


@pytest.fixture(scope="module")
def scales(tmp_path_factory):
    """By group, the μF of the polygons of forces_friction_10.svg and of forces_10.svg, off their captions."""
    folder = tmp_path_factory.mktemp("drawn")
    run(_scene(), folder, only=["forces"])
    found = {}
    for stem in (f"forces_friction_{NUMBER}", f"forces_{NUMBER}"):
        svg = (folder / f"{stem}.svg").read_text(encoding="utf-8")
        found[stem] = {}
        for group in set(POLYGON_OF.values()):
            caption = caption_text(svg, f"polygon-{group}")
            found[stem][group] = float(re.search(r"μF = ([0-9.]+) N/mm", caption).group(1))
    return found[f"forces_friction_{NUMBER}"], found[f"forces_{NUMBER}"]


def _readings(at, with_friction=True):
    return {name: round(_exact()[name][with_friction] / at[group], 2) for name, group in POLYGON_OF.items()}


def _far_off(warnings):
    return [line for line in warnings if f"measured.{NUMBER}:" in line]


def _listed(at):
    return ", ".join(f"{label} {at[group]:g}" for label, group in (("II(5,6)", "II-5-6"), ("II(3,4)", "II-3-4"),
                                                                    ("I(1,2)", "I-1-2")))


def test_the_friction_moves_the_reactions_beyond_the_bound_of_a_misreading():
    moved = {name: with_friction / plain - 1.0 for name, (plain, with_friction) in _exact().items()}
    assert sum(share > 0.15 for share in moved.values()) >= 4, moved


def test_readings_of_the_polygons_with_friction_are_told_that_drawing(tmp_path, scales):
    friction, plain = scales
    # Both sheets draw every polygon at one μF: it is listed once, the polygons without friction "at the same μF".
    assert friction == plain
    done = run(_scene(_readings(friction)), tmp_path, only=["forces", "errors", "note"])
    (warning,) = _far_off(done.warnings)
    assert (f"every reading of the force polygons fits the polygons with friction of position {NUMBER} in "
            f"forces_friction_{NUMBER}.svg at μF = {_listed(friction)} N/mm") in warning, warning
    assert f"not the polygons without friction of forces_{NUMBER}.svg (at the same μF)" in warning
    assert warning.count(_listed(friction)) == 1
    assert f"measure the polygons of forces_{NUMBER}.svg" in warning
    assert "force_scale" not in warning and "times" not in warning and "misread" not in warning
    results = json.loads((tmp_path / "results.json").read_text(encoding="utf-8"))
    assert [w["detail"] for w in results["warnings"] if w["code"] == "measured-far-off"] == [
        warning.split(": ", 1)[1]]
    errors = (tmp_path / "errors.md").read_text(encoding="utf-8")
    (line,) = [line for line in errors.splitlines() if "polygons with friction of position" in line]
    assert f"forces_friction_{NUMBER}.svg at μF = {_listed(friction)} N/mm" in line
    assert f"forces_{NUMBER}.svg (at the same μF)" in line and line.count(_listed(friction)) == 1
    assert f"Measure the polygons of forces_{NUMBER}.svg." in line
    assert "force_scale" not in errors and "stands nearer the polygons with friction" not in errors
    (said,) = [line for line in (tmp_path / "note.md").read_text(encoding="utf-8").splitlines()
               if "as the force analysis with friction draws them" in line]
    assert f"μF = {_listed(friction)} N/mm" in said and ".svg" not in said
    assert "without friction (at the same μF)" in said and said.count(_listed(friction)) == 1


def test_every_locale_tells_the_polygons_with_friction_in_its_words(tmp_path, scales):
    friction, _ = scales
    for locale, words, words_same in (("ru", "многоугольниками положения 10 с учётом трения", "(в том же масштабе)"),
                                      ("zh", "第 10 位置计摩擦的力多边形", "（比例尺相同）")):
        folder = tmp_path / locale
        run(_scene(_readings(friction), locale), folder, only=["forces", "errors"])
        errors = (folder / "errors.md").read_text(encoding="utf-8")
        line = next(line for line in errors.splitlines() if words in line)
        assert f"forces_friction_{NUMBER}.svg" in line and f"forces_{NUMBER}.svg" in line
        assert line.count(f"II(3,4) {friction['II-3-4']:g}") == 1 and "force_scale" not in errors
        assert words_same in line


def test_readings_of_the_polygons_without_friction_are_told_as_before(tmp_path, scales):
    _, plain = scales
    assert not _far_off(run(_scene(_readings(plain, False)), tmp_path / "right", only=["forces"]).warnings)
    # Every polygon drawn at 8 N/mm, the record's μF of none: the key is told, not the polygons with friction.
    other = {group: 8.0 for group in plain}
    assert 8.0 not in plain.values()
    (detail,) = _far_off(run(_scene(_readings(other, False)), tmp_path / "other", only=["forces"]).warnings)
    assert "force_scale = 8" in detail and "with friction" not in detail


def test_a_run_that_draws_no_force_sheet_says_what_it_said(tmp_path, scales):
    friction, _ = scales
    (detail,) = _far_off(run(_scene(_readings(friction)), tmp_path, only=["errors"]).warnings)
    assert "forces_friction" not in detail


def test_one_reading_alone_of_a_polygon_with_friction_is_told_that_polygon(tmp_path, scales):
    """R45, 38 % longer with friction, the one reading of its polygon, read off forces_friction_10.svg; the other
    polygons' readings off forces_10.svg."""
    friction, plain = scales
    plain_share = _exact()["R45"][1] / _exact()["R45"][0] - 1.0
    assert plain_share > 0.15
    readings = {name: length for name, length in _readings(plain, False).items() if POLYGON_OF[name] != "II-5-6"}
    readings["R45"] = _readings(friction)["R45"]
    (detail,) = _far_off(run(_scene(readings), tmp_path, only=["forces"]).warnings)
    assert (f"every reading of the force polygon II(5,6) fits the polygons with friction of position {NUMBER} in "
            f"forces_friction_{NUMBER}.svg at μF = {friction['II-5-6']:g} N/mm") in detail, detail
    assert "force_scale" not in detail and "misread" not in detail
