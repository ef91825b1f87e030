"""Force readings measured on the arrows of the groups cut free that the record's force sheet with friction,
forces_friction_N.svg, draws beside its polygons at a μF of their own (the shaper starter with the ram's slide at
f = 0.3, position 10: group II(3,4)'s arrows at 40 N/mm, the crank's at 50, against 25 and 40 in forces_10.svg and
polygons at 20 and 10). They were told misread, or a `[drawing] force_scale`; they are now told the arrows with
friction, in forces_friction_10.svg at their μF, and to measure the polygons of forces_10.svg, with no factor: the
readings are reactions with friction, and times any factor they are still not the reactions without friction the
error tables compare with.

The μF are read off the captions of the SVGs, the arrows drawn whole off its elements (a ruler on each gives the
reading), and each reading is the reaction with friction of results.json over its arrows' μF.
"""

import json
import math
import re

import pytest
from drawn_lines import arrow_length, caption_text
from sheet_texts import flat
from test_misread_record_friction_polygons import NUMBER, _far_off, _scene

from graphplan.run import run

# Group II(3,4) cut free draws R23 and R14 whole, the crank R12 (and R32, R23 again, which a scene reads once); group
# II(5,6) draws R45 in components, and its R16 is moved by under 1 % by the friction: it tells nothing apart.
ARROW_OF = {"R23": "II-3-4", "R14": "II-3-4", "R12": "I-1-2"}
LABEL = {"II-3-4": "II(3,4)", "I-1-2": "I(1,2)"}


@pytest.fixture(scope="module")
def drawn(tmp_path_factory):
    """The SVGs of forces_friction_10.svg and forces_10.svg, and by reaction its value (N) with friction and without,
    as results.json gives them."""
    folder = tmp_path_factory.mktemp("drawn")
    run(_scene(), folder, only=["forces"])
    svgs = {stem: (folder / f"{stem}.svg").read_text(encoding="utf-8")
            for stem in (f"forces_friction_{NUMBER}", f"forces_{NUMBER}")}
    results = json.loads((folder / "results.json").read_text(encoding="utf-8"))
    (position,) = [each for each in results["positions"] if each["index"] == NUMBER and "forces" in each]
    forces = position["forces"]

    def magnitude(reactions, name):
        return math.hypot(*reactions[name])

    exact = {name: (magnitude(forces["reactions"], name), magnitude(forces["friction"]["reactions"], name))
             for name in ARROW_OF}
    return svgs, exact


def _scales(svg, word):
    captions = flat(svg)
    return {group: float(re.search(word + r"μF = ([0-9.]+) N/mm", caption_text(captions, f"{element}-{group}")).group(1))
            for group, element in (("II-3-4", "body" if word else "polygon"), ("I-1-2", "body" if word else "polygon"))}


def _readings(svgs, exact):
    arrows = _scales(svgs[f"forces_friction_{NUMBER}"], "arrows: ")
    return {name: round(exact[name][1] / arrows[group], 2) for name, group in ARROW_OF.items()}, arrows


def _listed(scales):
    return ", ".join(f"{LABEL[group]} {scales[group]:g}" for group in ("II-3-4", "I-1-2"))


def test_the_arrows_with_friction_are_drawn_at_another_uf_and_length_than_the_others(drawn):
    svgs, exact = drawn
    readings, arrows = _readings(svgs, exact)
    plain_arrows = _scales(svgs[f"forces_{NUMBER}"], "arrows: ")
    polygons = _scales(svgs[f"forces_{NUMBER}"], "")
    for name, group in ARROW_OF.items():
        # The ruler on the arrow with friction gives the reading.
        assert abs(arrow_length(svgs[f"forces_friction_{NUMBER}"], f"body-{group}-{name}") - readings[name]) < 0.05
        # Far off the polygon without friction, and off the arrows without friction by twice the drafting
        # precision (0.5 mm) and more.
        assert abs(readings[name] * polygons[group] / exact[name][0] - 1.0) > 0.15
        assert abs(exact[name][0] / plain_arrows[group] - readings[name]) > 2 * _scene().drawing.drafting_precision
    assert arrows != plain_arrows


def test_readings_of_the_arrows_with_friction_are_told_that_drawing_with_no_factor(tmp_path, drawn):
    svgs, exact = drawn
    readings, arrows = _readings(svgs, exact)
    polygons = _scales(svgs[f"forces_{NUMBER}"], "")
    done = run(_scene(readings), tmp_path, only=["forces", "errors", "note"])
    (warning,) = _far_off(done.warnings)
    assert (f"every reading of the force polygons fits the arrows of the groups cut free with friction of position "
            f"{NUMBER} in forces_friction_{NUMBER}.svg at μF = {_listed(arrows)} N/mm") in warning, warning
    assert (f"not the polygons without friction of forces_{NUMBER}.svg (at μF = {_listed(polygons)} N/mm), whose "
            f"reactions they are checked against") in warning
    assert warning.endswith(f"off the arrows? measure the polygons of forces_{NUMBER}.svg")
    assert "force_scale" not in warning and "times" not in warning and "misread" not in warning
    results = json.loads((tmp_path / "results.json").read_text(encoding="utf-8"))
    assert [w["detail"] for w in results["warnings"] if w["code"] == "measured-far-off"] == [
        warning.split(": ", 1)[1]]
    errors = (tmp_path / "errors.md").read_text(encoding="utf-8")
    (line,) = [line for line in errors.splitlines() if "arrows of the groups cut free with friction" in line]
    assert f"in forces_friction_{NUMBER}.svg at μF = {_listed(arrows)} N/mm" in line
    assert f"not the polygons without friction of forces_{NUMBER}.svg (at μF = {_listed(polygons)} N/mm)" in line
    assert line.endswith(f"Measure the polygons of forces_{NUMBER}.svg.") and "times" not in line
    assert "force_scale" not in errors and "stands nearer the polygons with friction" not in errors
    (said,) = [line for line in (tmp_path / "note.md").read_text(encoding="utf-8").splitlines()
               if "as the force analysis with friction draws them, at a μF of their own" in line]
    assert f"μF = {_listed(arrows)} N/mm" in said and "read off the arrows with friction" in said
    assert "multiplied" not in said and ".svg" not in said


def test_russian_and_chinese_tell_the_arrows_with_friction_in_their_words(tmp_path, drawn):
    svgs, exact = drawn
    readings, arrows = _readings(svgs, exact)
    listed = _listed(arrows)
    folder = tmp_path / "ru"
    run(_scene(readings, "ru"), folder, only=["forces", "errors", "note"])
    (line,) = [line for line in (folder / "errors.md").read_text(encoding="utf-8").splitlines()
               if "со стрелками сил на отсоединённых группах положения 10 с учётом трения" in line]
    assert f"в forces_friction_{NUMBER}.svg при μF = {listed.replace('.', ',')} Н/мм" in line or \
        f"в forces_friction_{NUMBER}.svg при μF = {listed} Н/мм" in line, line
    assert line.endswith(f"Измерьте многоугольники forces_{NUMBER}.svg.") and "умножьте" not in line
    assert " с стрелками" not in line
    (said,) = [line for line in (folder / "note.md").read_text(encoding="utf-8").splitlines()
               if "согласуются со стрелками сил на отсоединённых группах положения 10 с учётом трения, как" in line]
    assert "умножить" not in said and "без учёта трения" in said and ".svg" not in said
    folder = tmp_path / "zh"
    run(_scene(readings, "zh"), folder, only=["forces", "errors"])
    (line,) = [line for line in (folder / "errors.md").read_text(encoding="utf-8").splitlines()
               if "第 10 位置计摩擦时各分离杆组上的力箭头" in line]
    assert f"forces_friction_{NUMBER}.svg" in line and "乘以" not in line


def test_readings_of_the_arrows_without_friction_are_told_as_before(tmp_path, drawn):
    """The arrows of forces_10.svg, without friction: still told that sheet's arrows and the factor to its polygons."""
    svgs, exact = drawn
    plain_arrows = _scales(svgs[f"forces_{NUMBER}"], "arrows: ")
    readings = {name: round(exact[name][0] / plain_arrows[group], 2) for name, group in ARROW_OF.items()}
    (warning,) = _far_off(run(_scene(readings), tmp_path, only=["forces"]).warnings)
    assert (f"fits the arrows of the groups cut free of position {NUMBER} in forces_{NUMBER}.svg at μF = "
            f"{_listed(plain_arrows)} N/mm") in warning, warning
    assert "give these readings times" in warning and "with friction" not in warning
