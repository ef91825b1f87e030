"""A polygon whose readings are partly off the drawing with friction and partly off the polygon without it (one
reaction measured on forces_friction_N.svg, the others on forces_N.svg, as asked): the readings that fit the drawing
with friction are named as such, with the same advice to measure forces_N.svg, and the others accepted.  The one read
with friction was told "a length misread, or a segment taken for another?".

The shaper starter with the ram's slide at f = 0.3, position 10 (as in test_misread_record_friction_polygons): group
II(3,4)'s polygon finds R23, R14 and R43, each 31 to 32 % longer with friction.  Each reading is the reaction of the
linear system, with friction or without, over its polygon's μF off the captions of forces_friction_10.svg and
forces_10.svg.
"""

import json
import re

from drawn_lines import caption_text
from test_misread_record_friction_polygons import NUMBER, POLYGON_OF, _exact, _far_off, _readings, _scene, scales

from graphplan.run import run

__all__ = ["scales"]  # the fixture, by which pytest finds it here


def _mixed(scales, with_friction):
    """The plain readings of every polygon, but those named in ``with_friction`` read off forces_friction_10.svg."""
    friction, plain = scales
    readings = _readings(plain, False)
    readings.update({name: _readings(friction)[name] for name in with_friction})
    return readings


def test_the_friction_moves_group_ii_3_4s_reactions_beyond_a_misreading():
    for name in ("R23", "R14", "R43"):
        plain, with_friction = _exact()[name]
        assert with_friction / plain - 1.0 > 0.15, name


def test_one_reaction_read_with_friction_is_named_the_others_accepted(tmp_path, scales):
    friction, _ = scales
    readings = _mixed(scales, ("R23",))
    done = run(_scene(readings), tmp_path, only=["forces", "errors", "note"])
    (warning,) = _far_off(done.warnings)
    assert (f"readings of the force polygon II(3,4) that fit the polygons with friction of position {NUMBER} in "
            f"forces_friction_{NUMBER}.svg at μF = {friction['II-3-4']:g} N/mm") in warning, warning
    assert f"the polygons without friction of forces_{NUMBER}.svg (at the same μF)" in warning
    assert f"checked against: R23 = {readings['R23']:g} mm;" in warning
    assert f"measure these on the polygons of forces_{NUMBER}.svg" in warning
    assert "R14" not in warning and "R43" not in warning
    assert "misread" not in warning and "force_scale" not in warning and "times" not in warning
    results = json.loads((tmp_path / "results.json").read_text(encoding="utf-8"))
    assert [w["detail"] for w in results["warnings"] if w["code"] == "measured-far-off"] == [
        warning.split(": ", 1)[1]]
    errors = (tmp_path / "errors.md").read_text(encoding="utf-8")
    (line,) = [line for line in errors.splitlines() if "with friction of position" in line]
    assert line.startswith("Readings of the force polygon II(3,4) that fit the polygons with friction of position")
    assert f"forces_friction_{NUMBER}.svg at μF = {friction['II-3-4']:g} N/mm" in line
    assert f"checked against: R23 = {readings['R23']:g} mm." in line and "R14" not in line
    assert line.endswith(f"Measure these on the polygons of forces_{NUMBER}.svg.")
    assert "A length misread" not in errors and "stands nearer the polygons with friction" not in errors
    (said,) = [line for line in (tmp_path / "note.md").read_text(encoding="utf-8").splitlines()
               if "as the force analysis with friction draws them" in line]
    assert f"R23 = {readings['R23']:g} mm" in said and ".svg" not in said and "R14" not in said


def test_two_reactions_read_with_friction_are_named_in_every_locale(tmp_path, scales):
    readings = _mixed(scales, ("R23", "R43"))
    (warning,) = _far_off(run(_scene(readings), tmp_path / "en", only=["forces"]).warnings)
    assert f"R23 = {readings['R23']:g} mm, R43 = {readings['R43']:g} mm;" in warning and "R14" not in warning
    for locale, words, same in (("ru", "Замеры на силовом многоугольнике II(3,4), согласующиеся",
                                 "(в том же масштабе)"), ("zh", "力多边形 II(3,4)的实测值", "（比例尺相同）")):
        folder = tmp_path / locale
        run(_scene(readings, locale), folder, only=["forces", "errors"])
        mark = "," if locale == "ru" else "."
        (line,) = [line for line in (folder / "errors.md").read_text(encoding="utf-8").splitlines() if words in line]
        assert f"R23 = {readings['R23']:g}".replace(".", mark) in line and "R14" not in line
        assert same in line and f"forces_friction_{NUMBER}.svg" in line


def test_a_reading_far_off_both_polygons_is_still_told_misread(tmp_path, scales):
    """R23 read 10 % beyond its reaction with friction: on neither drawing, the others of its polygon as asked."""
    readings = _mixed(scales, ())
    readings["R23"] = round(_readings(scales[0])["R23"] * 1.1, 2)
    (warning,) = _far_off(run(_scene(readings), tmp_path, only=["forces"]).warnings)
    assert "a length misread" in warning and "with friction" not in warning


def test_a_run_that_draws_no_force_sheet_tells_the_reading_misread(tmp_path, scales):
    (warning,) = _far_off(run(_scene(_mixed(scales, ("R23",))), tmp_path, only=["errors"]).warnings)
    assert "a length misread" in warning and "forces_friction" not in warning
    assert set(POLYGON_OF) >= {"R23", "R14", "R43"}


def test_one_reaction_read_off_the_arrows_with_friction_is_named_that_drawing(tmp_path, scales):
    """R23 measured on group II(3,4)'s arrow in forces_friction_10.svg, at the μF its caption gives the arrows."""
    svg_folder = tmp_path / "drawn"
    run(_scene(), svg_folder, only=["forces"])
    caption = caption_text((svg_folder / f"forces_friction_{NUMBER}.svg").read_text(encoding="utf-8"), "body-II-3-4")
    arrows = float(re.search(r"arrows: μF = ([0-9.]+) N/mm", caption).group(1))
    assert arrows != scales[1]["II-3-4"]
    readings = _mixed(scales, ())
    readings["R23"] = round(_exact()["R23"][1] / arrows, 2)
    (warning,) = _far_off(run(_scene(readings), tmp_path / "read", only=["forces"]).warnings)
    assert (f"readings of the force polygon II(3,4) that fit the arrows of the groups cut free with friction of "
            f"position {NUMBER} in forces_friction_{NUMBER}.svg at μF = {arrows:g} N/mm") in warning, warning
    assert f"forces_{NUMBER}.svg (at μF = {scales[1]['II-3-4']:g} N/mm)" in warning
    assert f"checked against: R23 = {readings['R23']:g} mm;" in warning and "misread" not in warning
