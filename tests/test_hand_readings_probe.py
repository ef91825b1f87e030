"""A student's hand-drawn plans checked with graphplan: the slips a student makes in ``[measured.N]`` (a balancing
moment signed as drawn, lengths typed in centimetres or metres) are each told with the key and what was meant.

Every reading here is a length of the plans as the program constructs them, or the balancing moment, worked out in the
test from the scene's scales and the exact solution, never taken from a warning's text.
"""


import dataclasses
import math
import re

import pytest

import graphplan
from graphplan.analysis import analyse
from graphplan.report.tables import markdown

FIXTURE = "fixtures/offset_slider_crank.toml"
POSITION = 3


def _with(block):
    return graphplan.load_text(open(FIXTURE, encoding="utf-8").read() + "\n" + block + "\n")


def test_a_balancing_moment_signed_as_drawn_is_refused_with_its_size_to_give():
    with pytest.raises(graphplan.GraphplanError) as caught:
        _with(f"[measured.{POSITION}]\nbalancing = -35.5")
    message = str(caught.value)
    assert message.startswith(f"measured.{POSITION}.balancing: must be >= 0"), message
    assert "give its size, balancing = 35.5" in message, message
    assert "sense is taken from the force analysis" in message, message


def _velocity_plan_lengths(number=POSITION):
    """pb, ab, ps3 (mm) of position ``number``'s velocity plan (3's unless said), worked out here from the offset slider-crank's closed form:
    A on the crank (r = 0.08 m at ω = 6.3 rad/s), B on the guide y = 0.08 m ahead of A (AB = 0.26 m), S3 AB's middle,
    μV = ω·r / 80 mm (velocity_pole = 80)."""
    analysis = analyse(dataclasses.replace(graphplan.load(FIXTURE), measured={}))
    phi = float(analysis.motion.driver[next(p for p in analysis.plans if p.number == number).index])
    r, length, e, omega = 0.08, 0.26, 0.08, 6.3
    ax, ay = r * math.cos(phi), r * math.sin(phi)
    bx = ax + math.sqrt(length**2 - (e - ay) ** 2)
    vax, vay = -omega * ay, omega * ax
    omega3 = -vay / (bx - ax)  # B moves along the guide: its velocity has no y part
    vbx = vax - omega3 * (e - ay)
    vs3 = (vax - omega3 * (e - ay) / 2, vay + omega3 * (bx - ax) / 2)
    scale = omega * r / 80.0
    return {"pb": abs(vbx) / scale, "ab": abs(omega3) * length / scale, "ps3": math.hypot(*vs3) / scale}


def _far_off(measured, locale="en"):
    scene = dataclasses.replace(graphplan.load(FIXTURE), locale=locale, measured={POSITION: measured})
    analysis = analyse(scene)
    (warning,) = [w for w in analysis.warnings if w.code == "measured-far-off"]
    return warning.detail, markdown(analysis)


def test_a_velocity_plan_typed_in_centimetres_is_told_so_not_as_a_pole_of_8_mm():
    lengths = _velocity_plan_lengths()
    detail, table = _far_off({"velocity": {name: round(value / 10.0, 2) for name, value in lengths.items()}})
    assert "a tenth: lengths typed in centimetres? give the millimetres measured (each reading times 10)" in detail
    assert "velocity_pole ≈" not in detail, detail
    assert ("Every reading of the velocity plan is 0.1 times its length as constructed, a tenth: lengths typed in "
            "centimetres? Give the millimetres measured (each reading times 10)") in table, table
    _, table = _far_off({"velocity": {name: round(value / 10.0, 2) for name, value in lengths.items()}}, "ru")
    assert "не введены ли длины в сантиметрах?" in table, table


def test_a_plan_typed_in_centimetres_is_told_the_key_it_would_give_sets_the_other_positions_too():
    """Position 10's plan typed in centimetres, position 3's in millimetres: the advice to give velocity_pole = 8
    (drawn at a tenth) did not say it would put position 3's right readings off, as a plan drawn at another pole is
    told."""
    readings = {3: {name: round(value, 2) for name, value in _velocity_plan_lengths(3).items()},
                10: {name: round(value / 10.0, 2) for name, value in _velocity_plan_lengths(10).items()}}
    scene = dataclasses.replace(graphplan.load(FIXTURE), measured={number: {"velocity": velocity}
                                                                   for number, velocity in readings.items()})
    analysis = analyse(scene)
    (detail,) = [w.detail for w in analysis.warnings if w.code == "measured-far-off"]
    assert detail.startswith("measured.10: every reading of the velocity plan is")
    assert "lengths typed in centimetres?" in detail
    assert ("; but velocity_pole sets the scale of position 3 too, whose readings fit the present scale and would then "
            "be off: rather keep it and give the readings of position 10 times") in detail, detail
    assert "But velocity_pole sets the scale of position 3 too" in markdown(analysis)


def test_one_reading_typed_in_centimetres_is_told_so():
    lengths = _velocity_plan_lengths()
    readings = {name: round(value, 1) for name, value in lengths.items()}
    readings["ps3"] = round(lengths["ps3"] / 10.0, 2)
    detail, table = _far_off({"velocity": readings})
    assert (f"readings a tenth of their lengths on the drawings (ps3 = {readings['ps3']:g} mm against "
            f"{lengths['ps3']:.4g} mm as constructed): lengths typed in centimetres?") in detail, detail
    assert "a length misread" not in detail
    assert f"ps3 = {readings['ps3']:g} mm against {lengths['ps3']:.4g} mm as constructed" in table, table
    _, table = _far_off({"velocity": readings}, "zh")
    assert "长度是否按厘米输入" in table, table


def test_the_error_table_tells_readings_in_metres_as_the_console_does_not_as_a_pole_of_0_1_mm():
    lengths = _velocity_plan_lengths()
    detail, table = _far_off({"velocity": {name: round(value / 1000.0, 5) for name, value in lengths.items()}})
    assert "lengths typed in metres?" in detail
    assert "lengths typed in metres? Give the millimetres measured (each reading times 1000)" in table, table
    assert "velocity_pole = 0.1" not in table, table
    readings = {name: round(value, 1) for name, value in lengths.items()}
    readings["pb"] = round(lengths["pb"] / 1000.0, 5)
    _, table = _far_off({"velocity": readings})
    assert (f"Readings a thousandth of their lengths on the drawings (pb = {readings['pb']:g} mm against "
            f"{lengths['pb']:.4g} mm as constructed): lengths typed in metres?") in table, table


def test_one_reading_typed_as_the_value_it_stands_for_is_told_so():
    """A student typed VE = 1.147 m/s for pe among readings in mm: it was named the acceleration plan's dn5, a segment
    it happened to be near.  Here pb is typed as VB in m/s, its length times μV = ω·r/80 (velocity_pole = 80)."""
    lengths = _velocity_plan_lengths()
    scale = 6.3 * 0.08 / 80.0
    readings = {name: round(value, 1) for name, value in lengths.items()}
    readings["pb"] = round(lengths["pb"] * scale, 4)
    detail, table = _far_off({"velocity": readings})
    told = (f"pb = {readings['pb']:g} mm is VB = {readings['pb']:.4g} m/s ({lengths['pb']:.4g} mm as constructed)")
    assert (f"readings that are the values they stand for, not their lengths on the drawings ({told}): give the "
            "millimetres measured") in detail, detail
    assert "a length misread" not in detail and "segment taken for another" not in detail, detail
    assert f"{told.replace(' (', ', ').rstrip(')')}" in table, table
    _, table = _far_off({"velocity": readings}, "ru")
    assert "Замеры, равные самим величинам" in table, table


def _crank_angle(fixture, number):
    analysis = analyse(dataclasses.replace(graphplan.load(fixture), measured={}))
    return float(analysis.motion.driver[next(p for p in analysis.plans if p.number == number).index])


def test_a_coriolis_component_typed_under_the_relative_segment_s_name_is_named():
    # The slotted lever's position 4 worked out here: crank OA = 0.12 m at ω = 8 rad/s about O = (0, 0.3), the lever
    # about C = (0, 0) through A; μa = ω²·OA / 100 mm (acceleration_pole = 100).
    fixture = "fixtures/quick_return_slotted_lever.toml"
    phi = _crank_angle(fixture, 4)
    r, omega = 0.12, 8.0
    ax, ay = r * math.cos(phi), 0.3 + r * math.sin(phi)
    vax, vay = -omega * r * math.sin(phi), omega * r * math.cos(phi)
    ca = math.hypot(ax, ay)
    sliding = (vax * ax + vay * ay) / ca
    omega4 = (ax * vay - ay * vax) / ca**2
    coriolis = 2.0 * abs(omega4 * sliding) / (omega**2 * r / 100.0)
    reading = round(coriolis, 1)
    scene = dataclasses.replace(graphplan.load(fixture), measured={4: {"acceleration": {"ka4": reading}}})
    analysis = analyse(scene)
    (warning,) = [w for w in analysis.warnings if w.code == "measured-far-off"]
    assert f"ka4 = {reading:g} mm is the acceleration plan's ak (aA4A3ᵏ) ({coriolis:.2f} mm as constructed)" \
        in warning.detail, warning.detail
    assert "a length misread" not in warning.detail
    scene = dataclasses.replace(scene, locale="ru")
    assert f"ka4 = {reading:g} мм — это отрезок ak (aA4A3ᵏ)".replace(".", ",") in markdown(analyse(scene))


def test_a_normal_component_typed_as_the_tangential_one_is_named():
    lengths = _velocity_plan_lengths()
    # aBAⁿ = VBA² / AB at μa = ω²·r / 80 mm, VBA = ab·μV.
    normal = (lengths["ab"] * 6.3 * 0.08 / 80.0) ** 2 / 0.26 / (6.3**2 * 0.08 / 80.0)
    detail, _ = _far_off({"acceleration": {"n3b": round(normal, 1)}})
    assert f"n3b = {round(normal, 1):g} mm is the acceleration plan's an3 (aBAⁿ) ({normal:.2f} mm" in detail, detail


def test_a_reaction_read_at_the_free_body_arrows_scale_is_named_with_that_scale():
    # The force sheet of position 3 draws both polygons at μF = 4 N/mm and the group's free-body arrows at 20 N/mm;
    # R23 from all the equilibrium equations solved at once (the error table's reference), read at 20 N/mm.
    scene = graphplan.load(FIXTURE)
    index = next(p for p in analyse(dataclasses.replace(scene, measured={})).plans if p.number == POSITION).index
    r23 = abs(scene.analyse().equilibrium.reaction("R23").force[index])
    reading = round(r23 / 20.0, 1)
    others = {name: round(abs(scene.analyse().equilibrium.reaction(name).force[index]) / 4.0, 1)
              for name in ("R34", "R14", "R12")}
    detail, table = _far_off({"forces": {"R23": reading, **others}})
    assert (f"R23 = {reading:g} mm at μF = 4 N/mm is R23 at μF = 20 N/mm ({r23 / 20.0:.2f} mm there), not at its "
            "polygon's: read off the free-body arrows") in detail, detail
    assert "velocity plan" not in detail, detail
    assert f"R23 = {reading:g} mm is R23 at μF = 20 N/mm ({r23 / 20.0:.2f} mm there)" in table, table


def test_errors_md_letters_the_relative_acceleration_as_the_note_does_not_with_a_caret():
    scene = graphplan.load("fixtures/quick_return_slotted_lever.toml")
    table = markdown(analyse(dataclasses.replace(scene, measured={4: {"acceleration": {"ka4": 69.0}}})))
    assert "| aA4A3ʳ | m/s² |" in table, table
    assert "^r" not in table, table


def test_two_segments_of_the_acceleration_plan_swapped_are_asked_as_swapped():
    # pb and ab of position 3's acceleration plan worked out here: aA = −ω²·rA, ε2 = 0; B keeps to the guide, so
    # aB's y part is 0: ε3 = (ω3²·(e − yA) − aAy) / (xB − xA); μa = ω²·r / 80 mm.
    phi = _crank_angle(FIXTURE, POSITION)
    r, length, e, omega = 0.08, 0.26, 0.08, 6.3
    ax, ay = r * math.cos(phi), r * math.sin(phi)
    bx = ax + math.sqrt(length**2 - (e - ay) ** 2)
    omega3 = -omega * ax / (bx - ax)
    aax, aay = -omega**2 * ax, -omega**2 * ay
    epsilon3 = (omega3**2 * (e - ay) - aay) / (bx - ax)
    abx = aax - epsilon3 * (e - ay) - omega3**2 * (bx - ax)
    scale = omega**2 * r / 80.0
    pb, ab = abs(abx) / scale, math.hypot(epsilon3, omega3**2) * length / scale
    detail, table = _far_off({"acceleration": {"pb": round(ab, 1), "ab": round(pb, 1)}})
    assert f"pb = {round(ab, 1):g} mm is the acceleration plan's ab ({ab:.2f} mm as constructed)" in detail, detail
    assert f"ab = {round(pb, 1):g} mm is the acceleration plan's pb ({pb:.2f} mm as constructed)" in detail, detail
    assert detail.endswith("segments taken for one another?"), detail
    assert "Segments taken for one another?" in table and "read off the other plan" not in table, table


def test_a_chinese_error_table_sets_its_readings_and_caveats_close():
    """Said in Chinese, two readings typed in centimetres were joined with a Latin «; », and a caveat was joined on
    with a Latin space after the full stop («）。 但»)."""
    lengths = _velocity_plan_lengths()
    readings = {name: round(value, 1) for name, value in lengths.items()}
    readings["ps3"], readings["ab"] = round(lengths["ps3"] / 10.0, 2), round(lengths["ab"] / 10.0, 2)
    _, table = _far_off({"velocity": readings}, "zh")
    (said,) = [line for line in table.splitlines() if "长度是否按厘米输入" in line]
    assert "；" in said and "; " not in said, said
    readings = {3: {name: round(value, 2) for name, value in _velocity_plan_lengths(3).items()},
                10: {name: round(value / 10.0, 2) for name, value in _velocity_plan_lengths(10).items()}}
    scene = dataclasses.replace(graphplan.load(FIXTURE), locale="zh",
                                measured={number: {"velocity": velocity} for number, velocity in readings.items()})
    lines = [line for line in markdown(analyse(scene)).splitlines() if "velocity_pole" in line]
    assert lines and not any(re.search(r"[。，；：）] ", line) for line in lines), lines
