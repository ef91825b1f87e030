"""An acceleration plan built with the Coriolis part laid off the wrong way, the slip the Coriolis part is known
for: every segment from it on is off, and the readings were told as so many lengths misread.

The student's plan is worked out here by hand, from the exact motion: for the slotted lever (block 3 on the crank
pin A, lever 4 about C), aA4 = aA + aA4A3ᵏ + aA4A3^r = aC + aA4Cⁿ + aA4C^τ, solved with aA4A3ᵏ = −2·ω4 × vA4A3.
"""

from __future__ import annotations

import json
import tomllib
from pathlib import Path

import numpy as np
import pytest

import graphplan
from graphplan.analysis import analyse
from graphplan.check import segment_millimetres
from graphplan.cli import main
from graphplan.plans import acceleration_plan

SCENE = Path("fixtures/quick_return_slotted_lever.toml")
NUMBER = 4


def _vector(array_row) -> complex:
    return complex(*array_row)


def _hand_plan(coriolis_sense: float) -> dict[str, float]:
    """The lengths (mm) a hand reads off position 4's acceleration plan, its Coriolis part laid off along
    ``coriolis_sense`` times 2·ω4 × vA4A3, at the scene's pole (πa = 100 mm)."""
    tables = tomllib.loads(SCENE.read_text(encoding="utf-8"))
    motion = graphplan.load(tables).solve()
    index = list(analyse(graphplan.load(tables)).positions.numbers).index(NUMBER)
    a_pin = _vector(motion.point("A").a[index])
    where_a, where_c = _vector(motion.point("A").r[index]), _vector(motion.point("C").r[index])
    omega4 = float(motion.link(4).omega[index])
    relative = _vector(motion.point("A4").v[index]) - _vector(motion.point("A").v[index])
    coriolis = coriolis_sense * 2j * omega4 * relative
    along = (where_a - where_c) / abs(where_a - where_c)
    normal = -omega4**2 * (where_a - where_c)
    # r·along − t·(i·along) = normal − aA − coriolis: the relative part along the slot, the tangential across CA.
    rhs = normal - a_pin - coriolis
    matrix = np.array([[along.real, -(1j * along).real], [along.imag, -(1j * along).imag]])
    sliding, tangential = np.linalg.solve(matrix, [rhs.real, rhs.imag])
    a_lever = normal + tangential * 1j * along
    per_mm = abs(a_pin) / tables["drawing"]["acceleration_pole"]
    lever_d = 0.55 / abs(where_a - where_c)  # D stands 0.55 m from C along CA
    return {"pa4": abs(a_lever) / per_mm, "ka4": abs(sliding) / per_mm, "n4a4": abs(tangential) / per_mm,
            "pd": abs(a_lever) * lever_d / per_mm}


def _scene(readings: dict[str, float]) -> dict:
    tables = tomllib.loads(SCENE.read_text(encoding="utf-8"))
    tables["measured"] = {str(NUMBER): {"acceleration": _as_read(readings)}}
    return tables


def _as_read(readings: dict[str, float]) -> dict[str, float]:
    """Lengths as a student reads them off the paper: to a tenth of a millimetre."""
    return {name: round(value, 1) for name, value in readings.items()}


def _far_off_warnings(tables: dict) -> list[str]:
    return [warning.detail for warning in analyse(graphplan.load(tables)).warnings
            if warning.code == "measured-far-off"]


def test_the_hand_plan_laid_off_rightly_is_the_construction():
    """The hand's plan, worked out here, is the program's where the Coriolis part is laid off as it should be: the
    readings taken off it are within the drafting precision, and nothing is told of them."""
    assert _far_off_warnings(_scene(_hand_plan(+1.0))) == []


def test_readings_of_a_plan_with_the_coriolis_part_reversed_are_told_so():
    reversed_plan, right = _hand_plan(-1.0), _hand_plan(+1.0)
    assert abs(reversed_plan["pa4"] - right["pa4"]) > 5.0  # far off the construction, and so told
    [told] = _far_off_warnings(_scene(reversed_plan))
    assert told.startswith(f"measured.{NUMBER}: every reading of the acceleration plan (pa4, ka4, n4a4, pd) fits the "
                           "plan with the Coriolis component aA4A3ᵏ laid off the other way")
    assert "2·ω × v_rel has the direction of v_rel turned by 90° in the sense of ω" in told
    assert told.endswith("was the Coriolis component laid off reversed?")
    assert "misread" not in told and "taken for" not in told and "times the plan" not in told


def test_one_misread_length_is_not_taken_for_a_reversed_coriolis_part():
    """A plan laid off rightly but for one length misread fits the reversed plan nowhere but by chance."""
    readings = _hand_plan(+1.0)
    readings["pd"] *= 1.4
    [told] = _far_off_warnings(_scene(readings))
    assert "laid off the other way" not in told
    assert "pd = 55.2 mm gives aD" in told and told.endswith("a length misread, or a segment taken for another?")


@pytest.mark.parametrize(("locale", "words"), [("en", "laid off reversed?"), ("ru", "отложено в обратную сторону?"),
                                               ("zh", "科氏加速度是否画反了？")])
def test_the_error_table_tells_it_in_the_scene_s_language(tmp_path, locale, words):
    errors, results = _error_table(tmp_path, SCENE, locale, NUMBER, _as_read(_hand_plan(-1.0)))
    assert words in errors and "aA4A3ᵏ" in errors
    assert any(warning["code"] == "measured-far-off" for warning in results["warnings"])


def _error_table(tmp_path: Path, scene: Path, locale: str, number: int, readings: dict[str, float]) -> tuple[str, dict]:
    """``errors.md`` and ``results.json`` of a run of ``scene`` in ``locale`` with ``readings`` of position
    ``number``'s acceleration plan."""
    text = scene.read_text(encoding="utf-8").replace('locale  = "en"', f'locale  = "{locale}"')
    assert f'locale  = "{locale}"' in text
    given = ", ".join(f"{name} = {value}" for name, value in readings.items())
    path = tmp_path / "scene.toml"
    path.write_text(f"{text}\n[measured.{number}]\nacceleration = {{ {given} }}\n", encoding="utf-8")
    assert main(["run", str(path), "--out", str(tmp_path / "out"), "--only", "errors", "--sheet", "none"]) == 0
    return ((tmp_path / "out" / "errors.md").read_text(encoding="utf-8"),
            json.loads((tmp_path / "out" / "results.json").read_text(encoding="utf-8")))


TANGENT = Path("fixtures/tangent_mechanism_prp.toml")


def _reversed_readings(reversed_parts: set[str]) -> tuple[int, dict, str]:
    """The tangent mechanism's position with plans, its Coriolis parts named in ``reversed_parts`` laid off
    reversed: its number, its readings (mm, to 0.1) taken off that plan, given as a student gives them, and the
    warning told."""
    tables = tomllib.loads(TANGENT.read_text(encoding="utf-8"))
    analysis = analyse(graphplan.load(tables))
    position = analysis.plans[0]
    plan = position.acceleration
    ends = {vector.end for step in plan.steps for vector in step.vectors if vector.meaning in reversed_parts}
    drawn = acceleration_plan(analysis.mechanism, position.positions, position.directions, position.velocity,
                              plan.scale, coriolis_reversed=ends)
    readings = {"".join(reading.segment): round(segment_millimetres(drawn, reading.segment), 1)
                for reading in position.readings if reading.plan == "acceleration"}
    tables["measured"] = {str(position.number): {"acceleration": readings}}
    [told] = _far_off_warnings(tables)
    return position.number, readings, told


@pytest.mark.parametrize("reversed_parts", [{"aA4A3ᵏ", "aBB4ᵏ"}, {"aA4A3ᵏ"}])
def test_of_two_coriolis_parts_the_ones_laid_off_reversed_are_named(reversed_parts):
    """The tangent mechanism lays off two Coriolis parts; a hand may turn one wrong and the other right."""
    *_, told = _reversed_readings(reversed_parts)
    many = len(reversed_parts) > 1
    named = told.split(f"fits the plan with the Coriolis component{'s' if many else ''} ")[1].split(" laid off")[0]
    assert set(named.split(" and ")) == reversed_parts
    assert told.endswith("were the Coriolis components laid off reversed?" if many
                         else "was the Coriolis component laid off reversed?")


def test_a_misread_length_beside_readings_the_coriolis_part_leaves_alone_is_told_misread():
    """πa is as long on either plan: beside it, pd = 67 mm (39.41 as constructed, 69.94 with the Coriolis part
    reversed) is one length misread, which one reading that tells the plans apart cannot tell from chance."""
    for readings in ({"pa": 100.0, "pd": 67.0}, {"pa": 100.0, "ps2": 41.5, "pd": 70.0}):
        [told] = _far_off_warnings(_scene(readings))
        assert "laid off the other way" not in told
        assert f"pd = {readings['pd']:g} mm gives aD" in told


def test_one_reading_alone_that_tells_a_part_reversed_is_no_proof_of_it():
    """aBB4ᵏ reversed alone moves pb alone of the tangent mechanism's segments: one length off, which chance may
    make (it is, to the drafting precision, the plan's pn4 too), is not told a part reversed."""
    *_, told = _reversed_readings({"aBB4ᵏ"})
    assert "laid off the other way" not in told and "pb = 24.7 mm" in told


def test_readings_that_tell_only_one_of_two_parts_name_that_one():
    """pa4, pd and n4a4 of the tangent mechanism hang on aA4A3ᵏ alone: aBB4ᵏ reversed too changes none of them, so
    only aA4A3ᵏ is named (both had been)."""
    number, readings, _ = _reversed_readings({"aA4A3ᵏ", "aBB4ᵏ"})
    tables = tomllib.loads(TANGENT.read_text(encoding="utf-8"))
    tables["measured"] = {str(number): {"acceleration": {name: readings[name] for name in ("pa4", "pd", "n4a4")}}}
    [told] = _far_off_warnings(tables)
    assert "with the Coriolis component aA4A3ᵏ laid off the other way" in told


@pytest.mark.parametrize(("locale", "words"), [
    ("en", "the Coriolis components aA4A3ᵏ, aBB4ᵏ laid off the other way"),
    ("ru", "кориолисовы ускорения aA4A3ᵏ, aBB4ᵏ отложены в обратную сторону"),
    ("zh", "（pa、ps2、pa4、")])
def test_two_parts_reversed_are_told_in_the_plural_in_the_error_table(tmp_path, locale, words):
    number, readings, _ = _reversed_readings({"aA4A3ᵏ", "aBB4ᵏ"})
    errors, _ = _error_table(tmp_path, TANGENT, locale, number, readings)
    assert words in errors


@pytest.mark.parametrize(("given", "error", "message"), [
    (True, TypeError, "a collection of the letters of Coriolis parts' ends"),
    ("k5", TypeError, "a collection of the letters"),
    (["zz"], ValueError, "zz ends no Coriolis part of the plan, whose parts end at k3, k5")])
def test_a_reversed_part_is_named_by_the_letters_the_plan_ends_them_at(given, error, message):
    """coriolis_reversed="k5" reversed nothing (taken as k and 5), and ["zz"] nothing, without a word."""
    analysis = analyse(graphplan.load(TANGENT))
    position = analysis.plans[0]
    with pytest.raises(error, match=message):
        acceleration_plan(analysis.mechanism, position.positions, position.directions, position.velocity,
                          coriolis_reversed=given)
