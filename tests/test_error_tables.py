"""Readings off the plans and their error tables (construction, drafting, measured)."""

import dataclasses
import json
import re
from pathlib import Path

import numpy as np
import pytest

import graphplan
from graphplan.analysis import analyse
from graphplan.check import split_segment
from graphplan.cli import main
from graphplan.errors import SceneError
from graphplan.locale import strings

FIXTURE = "fixtures/ratchet_crank_rocker.toml"


@pytest.fixture(scope="module")
def analysis():
    return analyse(graphplan.load(FIXTURE))


def rows(analysis, number, source):
    plan = next(p for p in analysis.plans if p.number == number)
    return {row.quantity: row for row in plan.errors if row.source == source}


def test_the_ratchet_report_carries_the_worked_examples_quantities(analysis):
    wanted = {"VA", "VB", "VS2", "VS3", "VS4", "VE", "VBA", "VBC", "omega3", "omega4",
              "aA", "aB", "aS2", "aS3", "aS4", "aE", "aBA", "aBC", "epsilon3", "epsilon4"}
    for number in (5, 11):
        assert wanted <= set(rows(analysis, number, "construction"))


def test_the_construction_agrees_with_the_analytic_solution(analysis):
    for number in (5, 11):
        for row in rows(analysis, number, "construction").values():
            assert abs(row.percent) < 1e-9, row


def test_the_measured_column_shows_the_worked_examples_own_readings(analysis):
    # shared/fixtures-data.md, "plan (printed)" at position 5: the readings come back as printed.
    measured = rows(analysis, 5, "measured")
    printed = {"VB": 0.77, "VS3": 1.755, "VE": 1.65, "VBA": 2.955, "omega3": -5.37, "omega4": 2.37,
               "aB": 32.87, "aS3": 42.73, "aS4": 14.16, "aE": 45.5, "epsilon3": -20.48, "epsilon4": -101.14}
    for quantity, value in printed.items():
        # printed to 3–4 digits: half a unit of the last one is within 1e-3 of the value
        assert measured[quantity].plan == pytest.approx(value, rel=1e-3), quantity
    # The contract's example row: ω4 = 2.37 against the exact 2.1554, about −10 %.
    assert measured["omega4"].percent == pytest.approx((2.155353 - 2.369) / 2.155353 * 100, abs=0.01)


def test_drafting_errors_shrink_with_the_drafting_precision():
    scene = graphplan.load(FIXTURE)
    worst = []
    for precision in (2.0, 0.5, 0.1, 0.01):
        finer = dataclasses.replace(scene, drawing=dataclasses.replace(scene.drawing, drafting_precision=precision))
        errors = [abs(r.percent) for p in analyse(finer).plans for r in p.errors if r.source == "drafting"]
        worst.append(max(errors))
    assert worst == sorted(worst, reverse=True)
    assert worst[-1] < worst[0] / 20


def test_a_drafted_reading_is_the_plan_length_rounded_to_the_precision(analysis):
    plan = next(p for p in analysis.plans if p.number == 5)
    reading = next(r for r in plan.readings if r.quantity == "VB")
    mm = reading.millimetres(plan.plans)
    drafted = rows(analysis, 5, "drafting")["VB"].plan
    assert drafted == pytest.approx(round(mm / 0.5) * 0.5 * plan.velocity.scale, rel=1e-12)
    assert drafted != pytest.approx(mm * plan.velocity.scale, rel=1e-6)


def test_results_json_carries_plans_and_errors(tmp_path):
    # results.json comes with every run, whatever its pieces: the error tables are the piece read here.
    assert main(["run", FIXTURE, "--out", str(tmp_path / "out"), "--only", "errors"]) == 0
    document = json.loads((tmp_path / "out" / "results.json").read_text(encoding="utf-8"))
    fifth = document["positions"][5]
    velocity = fifth["plans"]["velocity"]
    assert velocity["scale"] == pytest.approx(2.975 / 150)          # pa = 150 mm fixes μV
    assert np.hypot(*velocity["points_mm"]["a"]) == pytest.approx(150.0)
    assert fifth["plans"]["acceleration"]["scale"] == pytest.approx(50.575 / 100)
    assert velocity["values"]["omega4"] == pytest.approx(2.155353, rel=1e-6)
    assert "plans" not in document["positions"][4]
    sources = {row["source"] for row in document["errors"]}
    assert sources == {"construction", "drafting", "measured"}
    assert {"errors.md", "errors.csv"} <= {p.name for p in (tmp_path / "out").iterdir()}


def test_segment_names_split_into_plan_letters():
    letters = sorted(["p", "a", "b", "s3", "n3", "n4", "e"], key=len, reverse=True)
    assert split_segment("n3b", letters, "x") == ("n3", "b")
    assert split_segment("ps3", letters, "x") == ("p", "s3")
    with pytest.raises(SceneError, match="is not two letters of the plan"):
        split_segment("qz", letters, "measured.5.velocity.qz")


def with_measured(measured):
    return dataclasses.replace(graphplan.load(FIXTURE), measured=measured)


def test_a_segment_measured_twice_under_its_two_names_is_refused():
    # pb and bp are one segment: which reading would the table take?
    for kind, lengths, again in (("velocity", {"pb": 38.82, "bp": 40.0}, "bp"),
                                 ("acceleration", {"n3b": 22.27, "bn3": 20.0}, "bn3")):
        with pytest.raises(SceneError, match=rf"^measured\.5\.{kind}\.{again}: is the segment .* again"):
            analyse(with_measured({5: {kind: lengths}}))


def test_a_segment_of_plan_letters_no_quantity_is_read_from_names_the_segments_that_are(analysis):
    """pn3 joins two letters of the acceleration plan but gives no quantity: the error said so and no more,
    where a misspelt letter gets the plan's letters; now it names the segments there are."""
    with pytest.raises(SceneError, match=r"^measured\.5\.acceleration\.pn3: the plan has no quantity read from "
                                         r"pn3; its quantities are read from (.+)$") as refused:
        analyse(with_measured({5: {"acceleration": {"pb": 64.99, "pn3": 95.0}}}))
    offered = re.search(r"read from ([^;]+)$", str(refused.value))[1].split(", ")
    assert "pb" in offered and "pn3" not in offered
    every = analyse(with_measured({5: {"acceleration": dict.fromkeys(offered, 50.0)}}))
    measured = {row.quantity for row in every.errors if row.position == 5 and row.source == "measured"}
    assert measured == {row.quantity for row in analysis.errors if row.position == 5 and row.source == "construction"
                        and row.quantity[0] in "ae"}


def test_the_acceleration_plans_pole_may_be_written_as_it_is_drawn(analysis):
    # The plan draws its pole π (and the note writes πb·μa): a reading of πb is the one of pb.
    as_drawn = rows(analyse(with_measured({5: {"acceleration": {"πb": 64.99, "πs3": 84.49}}})), 5, "measured")
    as_named = rows(analysis, 5, "measured")
    for quantity in ("aB", "aS3"):
        assert as_drawn[quantity].plan == as_named[quantity].plan
        assert as_drawn[quantity].percent == as_named[quantity].percent
    with pytest.raises(SceneError, match=r"is no segment of the plan: π \(p\) is one of its letters, q is none"):
        analyse(with_measured({5: {"acceleration": {"πq": 10.0}}}))
    with pytest.raises(SceneError, match=r"is not two letters of the plan \(.*\) \(its pole π is p\)"):
        analyse(with_measured({5: {"acceleration": {"ob": 10.0}}}))


def test_the_csv_writes_an_error_of_rounding_as_none(tmp_path):
    # The constructed pb of position 5 is VB to rounding: its error of -3e-14 % is none, which results.json
    # writes as 0, and so does errors.csv.
    assert main(["run", FIXTURE, "--out", str(tmp_path / "out"), "--only", "errors"]) == 0
    lines = (tmp_path / "out" / "errors.csv").read_text(encoding="utf-8").splitlines()
    percents = {tuple(line.split(",")[:2] + line.split(",")[3:4]): line.split(",")[-1] for line in lines[1:]}
    document = json.loads((tmp_path / "out" / "results.json").read_text(encoding="utf-8"))
    for row in document["errors"]:
        written = percents[(str(row["position"]), row["quantity"], row["source"])]
        assert float(written) == pytest.approx(row["percent"], rel=1e-5, abs=0.0)
        assert "e-" not in written or abs(float(written)) > 1e-10
    assert percents[("5", "VB", "construction")] == "0"


def test_the_csv_leaves_the_error_of_a_reading_of_what_stands_still_empty_as_results_json_writes_null():
    """At the extreme position 0 the rocker stands still: a reading pb = 0.5 mm has no finite δ; errors.csv wrote
    inf where results.json writes null and the table —, and −0 for a rounding's nought."""
    from graphplan.report.results import results
    from graphplan.report.tables import csv_text

    scene = with_measured({0: {"velocity": {"pb": 0.5}}})
    analysis = analyse(dataclasses.replace(scene, positions=dataclasses.replace(scene.positions, plans=(0, 5, 11))))
    lines = csv_text(analysis).splitlines()
    assert not [line for line in lines if "inf" in line or ",-0," in line or line.endswith(",-0")]
    (row,) = [line.split(",") for line in lines if line.startswith("0,VB,") and ",measured," in line]
    assert row[-1] == ""
    (written,) = [e for e in results(analysis)["errors"]
                  if e["position"] == 0 and e["quantity"] == "VB" and e["source"] == "measured"]
    assert written["percent"] is None


def test_a_quantity_that_vanishes_at_the_position_has_no_error_of_rounding():
    # The Scotch yoke in position 4 (φ = 180°): the crank pin moves square to the slot, so the block
    # rests in it and the yoke does not accelerate; both solutions give zero up to rounding.
    analysis = analyse(graphplan.load("fixtures/scotch_yoke.toml"))
    for source in ("construction", "drafting"):
        table = rows(analysis, 4, source)
        for quantity in ("VA4A3", "aB", "aA4A1^r"):
            assert (table[quantity].analytic, table[quantity].plan, table[quantity].percent) == (0.0, 0.0, 0.0)
        assert table["aA4A3^r"].analytic == pytest.approx(12.566**2 * 0.075, rel=1e-9)


def test_the_markdown_table_writes_true_minus_signs_and_right_aligned_numbers(analysis):
    from graphplan.report.tables import markdown

    lines = [line for line in markdown(analysis).splitlines() if line.startswith("|")]
    assert any(line.startswith("| ω2 | рад/с | −17 | −17 | −17 |") for line in lines)  # clockwise at 17 rad/s
    for line in lines:
        cells = line.strip("|").split("|")[2:]
        assert not any("-" in cell for cell in cells if not set(cell.strip()) <= set("-:")), line
    assert all(line.startswith("|---|---|---:|") for line in lines if set(line) <= set("|-:"))


@pytest.mark.parametrize(("locale", "units"), [
    ("ru", {"V": "м/с", "a": "м/с²", "ω": "рад/с", "ε": "рад/с²", "R": "Н"}),
    ("en", {"V": "m/s", "a": "m/s²", "ω": "rad/s", "ε": "rad/s²", "R": "N"}),
])
def test_every_row_of_the_markdown_table_names_the_unit_of_its_quantity(analysis, locale, units):
    from graphplan.report.tables import markdown

    scene = dataclasses.replace(analysis.scene, locale=locale)
    rows_ = [[cell.strip() for cell in line.strip("|").split("|")[:2]]
             for line in markdown(dataclasses.replace(analysis, scene=scene)).splitlines()
             if line.startswith("| ") and not line.startswith(("| величина |", "| quantity |"))]
    # The last row of each table is no quantity: the largest δ of each source, in %.
    largest = strings(locale)["errors_largest"]
    assert all(unit == "%" for name, unit in rows_ if name == largest)
    rows_ = [row for row in rows_ if row[0] != largest]
    assert {quantity[0] for quantity, _ in rows_} == set(units)  # velocities to reactions, all present
    for quantity, unit in rows_:
        assert unit == units[quantity[0]], quantity


def test_a_reading_far_off_its_constructed_plan_is_warned_of(analysis):
    # The worked example's own readings are within 12 % of the construction (its ε3 the farthest): no warning.
    assert not [w for w in analysis.warnings if w.code == "measured-far-off"]
    constructed = rows(analysis, 5, "construction")["VB"].plan
    pb = constructed / (2.975 / 150) * 1.25  # the segment read 25 % long
    warned = analyse(with_measured({5: {"velocity": {"pb": pb}}}))
    (warning,) = [w for w in warned.warnings if w.code == "measured-far-off"]
    assert warning.position == 5 and warning.detail.startswith("measured.5: ")
    assert f"VB = {constructed * 1.25:.4g} against {constructed:.4g}, 25.0 % off" in warning.detail


def test_a_far_off_reading_is_named_as_the_scene_writes_it_with_the_scale_it_was_read_at(analysis):
    """The warning named quantities alone (a typo of pd showed as VD and ω4 off), and a reaction read as the
    polygon draws it (R43) showed under the other name at a μF the student could not see."""
    drawn = {name: found for name, found in analysis.plans[1].forces.reactions.items()}
    number = analysis.plans[1].number
    scale = analysis.plans[1].forces.scale_of("R34")
    assert "R34" in drawn
    pb = rows(analysis, number, "construction")["VB"].plan / analysis.plans[1].velocity.scale
    warned = analyse(with_measured({number: {"velocity": {"pb": pb * 10}, "forces": {"R43": 3.0}}}))
    (warning,) = [w for w in warned.warnings if w.code == "measured-far-off"]
    assert f"pb = {pb * 10:g} mm gives VB = " in warning.detail
    assert f"R43 = 3 mm at μF = {scale:g} N/mm gives R34 = {3.0 * scale:.4g} against " in warning.detail


@pytest.mark.parametrize(("pb", "warned"), [(0.5, False), (0.9, False), (3.0, True)])
def test_a_reading_of_a_vanishing_velocity_is_far_off_only_beyond_the_drafting_precision(pb, warned):
    """At the extreme position 0 the rocker is at rest: pb is 0 on the plan as constructed.  A reading of 0.5 mm
    was called infinitely far off ("inf %", a misread?) though it is within the drafting precision (0.5 mm) of
    both ends of the segment; its δ has no finite value and is written "—"."""
    from graphplan.report.tables import markdown

    scene = with_measured({0: {"velocity": {"pb": pb}}})
    scene = dataclasses.replace(scene, positions=dataclasses.replace(scene.positions, plans=(0, 5, 11)))
    analysis = analyse(scene)
    assert rows(analysis, 0, "construction")["VB"].plan == 0.0
    far = [w for w in analysis.warnings if w.code == "measured-far-off"]
    assert bool(far) is warned
    if warned:
        assert "VB = " in far[0].detail and "where the plan has none" in far[0].detail
    line = next(line for line in markdown(analysis).splitlines() if line.startswith("| VB |"))
    assert "inf" not in line and line.rstrip(" |").endswith("—")


def test_a_reading_of_nothing_gives_no_negative_zero():
    """pb read as 0 mm at position 11, where the rocker turns clockwise, was told as "omega4 = -0 against ..."."""
    analysis = analyse(with_measured({11: {"velocity": {"pb": 0.0}}}))
    assert rows(analysis, 11, "construction")["omega4"].plan < 0
    (warning,) = [w for w in analysis.warnings if w.code == "measured-far-off"]
    assert "ω4 = 0 against " in warning.detail and "-0 " not in warning.detail


def test_a_velocity_plan_drawn_at_another_scale_is_named_as_such_not_as_misread_lengths():
    """The worked example's readings at position 5 as a student would take them off a plan laid off with pa =
    100 mm instead of the scene's 150: every one is 2/3 of the construction, under its own few per cent.  That
    is one slip, the scale μV = VA/pa, not five misread lengths."""
    printed = {"pb": 38.82, "ab": 148.99, "ps3": 88.49, "pe": 83.19}
    analysis = analyse(with_measured({5: {"velocity": {name: mm * 100 / 150 for name, mm in printed.items()}
                                          | {"pa": 100.0}}}))
    (warning,) = [w for w in analysis.warnings if w.code == "measured-far-off"]
    assert "every reading of the velocity plan is" in warning.detail and "misread" not in warning.detail
    drawn_at = float(re.search(r"a plan drawn at μV = ([\d.]+)", warning.detail)[1])
    va = rows(analysis, 5, "construction")["VA"].plan
    assert drawn_at == pytest.approx(va / 100.0, rel=0.03)
    # One length misread among readings at the scene's scale is still a misread length.
    slipped = analyse(with_measured({5: {"velocity": printed | {"pb": printed["pb"] * 2 / 3}}}))
    (warning,) = [w for w in slipped.warnings if w.code == "measured-far-off"]
    assert "misread" in warning.detail and "every reading" not in warning.detail


def test_readings_given_as_the_values_in_their_units_are_named_as_such():
    """A student who typed VB in m/s where pb in mm was asked for was told of «a plan drawn at μV = 0.9867
    (m/s)/mm?»: a scale of one unit a millimetre is the values themselves."""
    from graphplan.report.tables import markdown

    exact = {name: abs(complex(*graphplan.solve(graphplan.load(FIXTURE)).point(point).v[5]))  # positions numbered from 0
             for name, point in (("pb", "B"), ("pe", "E"))}
    analysis = analyse(dataclasses.replace(with_measured({5: {"velocity": {name: value * 1.01
                                                                          for name, value in exact.items()}}}),
                                           locale="en"))
    (warning,) = [w for w in analysis.warnings if w.code == "measured-far-off"]
    assert "is the value it stands for, in m/s, not its length on the plan" in warning.detail
    assert "a plan drawn at" not in warning.detail
    assert "Every reading of the velocity plan is the value it stands for" in markdown(analysis)


def test_the_error_tables_say_under_a_position_which_readings_are_far_off_in_the_scenes_language():
    """The warning went to the terminal and results.json alone; the student reads errors.md and the note."""
    from graphplan.report.note import note_markdown
    from graphplan.report.tables import markdown

    printed = {"pb": 38.82, "ab": 148.99, "ps3": 88.49, "pe": 83.19}
    # pb 1.45 times, not 1.3: 84.487 mm is the acceleration plan's ps3 (84.75 mm) to 0.5 mm, and is named so.
    measured = {5: {"velocity": {name: mm * 100 / 150 for name, mm in printed.items()},
                    "acceleration": {"pb": 64.99 * 1.45, "ps3": 84.49}}}
    scene = dataclasses.replace(with_measured(measured), locale="ru")
    analysis = analyse(scene)
    (warning,) = [w for w in analysis.warnings if w.code == "measured-far-off"]
    drawn_at = re.search(r"a plan drawn at μV = ([\d.]+)", warning.detail)[1].replace(".", ",")
    for text in (markdown(analysis), note_markdown(analysis)):
        assert f"не построен ли план в масштабе μV = {drawn_at} (м/с)/мм (velocity_pole ≈ " in text
        assert "Укажите `[drawing] velocity_pole = 100`" in text  # pa = 100 mm, as the readings were made
        assert "более чем на 15 % и на 1 мм: pb = 94,2355 мм (aB, aBC)." in text
    assert "замеры" not in markdown(analyse(dataclasses.replace(graphplan.load(FIXTURE), locale="ru"))).lower()


def test_measuring_the_coriolis_segment_is_answered_with_why_it_gives_nothing():
    scene = graphplan.load("fixtures/quick_return_slotted_lever.toml")
    number = scene.positions.plans[0]
    with pytest.raises(SceneError, match=rf"^measured\.{number}\.acceleration\.ak: the plan has no quantity read from "
                                         r"ak \(ak is the Coriolis component, laid off from 2·ω·v, not read off\); "
                                         r"its quantities are read from .*ka4"):
        analyse(dataclasses.replace(scene, measured={number: {"acceleration": {"ak": 16.0}}}))


@pytest.mark.parametrize("segment", ["an3", "n3a", "pn4"])
def test_measuring_a_normal_component_is_answered_with_why_it_gives_nothing(segment):
    """an3 is aBAⁿ, lettered on the acceleration plan: "the plan has no quantity read from an3" read as a wrong
    name, not as a component laid off from ω²·l, which checks the arithmetic and not the drawing."""
    written = segment  # as the student wrote it, either way round
    meaning = "aBCⁿ" if segment == "pn4" else "aBAⁿ"
    with pytest.raises(SceneError, match=rf"^measured\.5\.acceleration\.{segment}: the plan has no quantity read from "
                                         rf"{written} \({written} is the normal component {meaning}, laid off from ω²·l "
                                         r"= v²/l, not read off: the tangential component beside it gives ε\); its "
                                         r"quantities are read from .*n3b, n4b$"):
        analyse(with_measured({5: {"acceleration": {segment: 12.7}}}))


# An oscillating cylinder: crank OA turns the cylinder (lever 4) about A, whose rod's block 3 pivots on the
# frame at P; so P3 is at the pole and the sliding velocity laid from it is vP4P3.
OSCILLATING_CYLINDER = """
[scene]
title = "Oscillating cylinder"

[frame]
link = 1
points = { O = [0.0, 0.0], P = [0.3, 0.0] }

[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = 0.1
omega = 15.0

[[groups]]
kind = "RPR"
links = [3, 4]
joints = ["P", "A"]

[positions]
count = 12
plans = [3]

[measured.3]
velocity = { pp4 = 49.0 }
"""


def test_the_sliding_of_a_block_pivoted_on_the_frame_is_named_as_its_equation_names_it():
    """The rows read VP4P3P4 (the vector's own name with the pair's joint and guide added again), though the
    note's equation writes vP4 = vP3 + vP4P3; a hand reading of pp4 landed on that garbled row."""
    analysis = analyse(graphplan.load_text(OSCILLATING_CYLINDER))
    plan = analysis.plans[0]
    quantities = {row.quantity for row in plan.errors}
    assert {"VP4P3", "aP4P3^r"} <= quantities
    assert not [quantity for quantity in quantities if "P4P3P" in quantity]
    # ṡ and s̈ of the rod in the cylinder are the rates of the distance PA: s = |A − P|.
    a, p, omega = plan.positions["A"], plan.positions["P"], 15.0
    pa, v_a, a_a = a - p, 1j * omega * a, -omega**2 * a
    s = abs(pa)
    s_dot = (pa.conjugate() * v_a).real / s
    s_ddot = (abs(v_a) ** 2 + (pa.conjugate() * a_a).real - s_dot**2) / s
    construction = rows(analysis, 3, "construction")
    assert construction["VP4P3"].plan == pytest.approx(abs(s_dot), rel=1e-9)
    assert construction["aP4P3^r"].plan == pytest.approx(abs(s_ddot), rel=1e-9)
    measured = rows(analysis, 3, "measured")
    assert set(measured) == {"VP4", "VP4P3"}  # P3 is at the pole: pp4 is vP4 as well
    assert measured["VP4P3"].plan == pytest.approx(49.0 * plan.velocity.scale, rel=1e-12)


def test_a_point_named_k_keeps_its_letter_and_the_coriolis_end_takes_the_sliders_number():
    """With a point K on the crank the Coriolis end was k′, which Chinese notation reads as K's own image on the
    acceleration plan; and a reading from k (K's image) was refused as 'the Coriolis component'.  Now the Coriolis
    end is k3 (block 3's), in the plans and their readings alike, and k is K's: πk reads aK, which is checked
    here against aK = (iε2 − ω2²)·OK of the crank turning at the fixture's ω2 = 8 rad/s, ε2 = 0."""
    text = Path("fixtures/quick_return_slotted_lever.toml").read_text(encoding="utf-8")
    text = text.replace("[points]\n", '[points]\nK  = { link = 2, from = "O", toward = "A", at = 0.09, offset = 0.04 }\n')
    scene = graphplan.scene.loads(text)
    number = scene.positions.plans[0]
    plan = next(p for p in analyse(scene).plans if p.number == number)
    coriolis = [v for step in plan.acceleration.steps for v in step.vectors if v.meaning.endswith("ᵏ")]
    assert [(v.start, v.end) for v in coriolis] == [("a", "k3")]
    assert not [letter for letter in plan.acceleration.points if "′" in letter]
    a_k = (0j - 8.0**2) * (plan.positions["K"] - plan.positions["O"])
    assert abs(plan.acceleration.value("K")) == pytest.approx(abs(a_k), rel=1e-9)
    pk = abs(a_k) / plan.acceleration.scale
    measured = analyse(dataclasses.replace(scene, measured={number: {"acceleration": {"πk": pk}}}))
    (row,) = [r for r in measured.errors if r.position == number and r.source == "measured"]
    assert (row.quantity, row.plan) == ("aK", pytest.approx(abs(a_k), rel=1e-12))
    with pytest.raises(SceneError, match=r"no quantity read from ak3 \(ak3 is the Coriolis component"):
        analyse(dataclasses.replace(scene, measured={number: {"acceleration": {"ak3": 10.0}}}))
    with pytest.raises(SceneError, match=r"no quantity read from ka4; its quantities are read from .*k3a4"):
        analyse(dataclasses.replace(scene, measured={number: {"acceleration": {"ka4": 10.0}}}))


def test_a_plan_at_another_scale_is_told_the_key_to_give_and_how_close_the_readings_come_there():
    """The hint gave the median's μV and said "set at that scale, the readings agree" while pb read 7.9 % off there,
    and named no key: readings of the worked example doubled, as off a plan laid off with pa = 300 mm."""
    printed = {"pb": 77.64, "ab": 297.98, "ps3": 176.98, "pe": 166.38}  # the worked example's readings, doubled
    scene = with_measured({5: {"velocity": printed}})
    motion = graphplan.solve(scene)
    v = {name: complex(*motion.point(name).v[5]) for name in ("A", "B", "S3", "E")}
    exact = {"pb": abs(v["B"]), "ab": abs(v["B"] - v["A"]), "ps3": abs(v["S3"]), "pe": abs(v["E"])}
    at_300 = abs(v["A"]) / 300.0  # μV of a plan with pa = 300 mm
    off = max(abs(mm * at_300 / exact[name] - 1.0) for name, mm in printed.items()) * 100.0
    assert off > 5.0  # the readings do not agree at any scale to better than their own errors
    (warning,) = [w for w in analyse(scene).warnings if w.code == "measured-far-off"]
    assert "agree" not in warning.detail
    assert "velocity_pole ≈ 305.5 mm? give `[drawing] velocity_pole = 300`" in warning.detail
    within = float(re.search(r"every reading is within ([\d.]+) % of the plan as constructed", warning.detail)[1])
    assert within == pytest.approx(off, abs=0.06)


def test_readings_of_a_plan_at_a_scale_given_directly_are_told_that_key():
    scene = with_measured({5: {"velocity": {"pb": 77.64, "ab": 297.98, "ps3": 176.98, "pe": 166.38}}})
    drawing = dataclasses.replace(scene.drawing, velocity_scale=0.02, velocity_pole=None)
    (warning,) = [w for w in analyse(dataclasses.replace(scene, drawing=drawing)).warnings
                  if w.code == "measured-far-off"]
    assert "give `[drawing] velocity_scale = 0.01`" in warning.detail and "velocity_pole" not in warning.detail


COARSE = "rounded to 100 mm and a hand reading is far off only beyond 200 mm"


@pytest.mark.parametrize(("precision", "told"), [(100.0, COARSE), (0.01, "finer than a ruler reads"),
                                                 (0.5, None), (2.0, None), (0.05, None)])
def test_a_drafting_precision_no_ruler_reads_is_told_by_check_and_run(tmp_path, capsys, precision, told):
    """drafting_precision = 100 (a slip for 1.0) rounded every drafted length to 0 or 100 mm and raised the far-off
    threshold to 200 mm without a word, where a force_scale that draws a polygon too small to read is told."""
    text = Path(FIXTURE).read_text(encoding="utf-8")
    assert "drafting_precision = 0.5" in text
    scene = tmp_path / "scene.toml"
    scene.write_text(text.replace("drafting_precision = 0.5", f"drafting_precision = {precision}"), encoding="utf-8")
    assert main(["check", str(scene)]) == 0
    printed = capsys.readouterr()
    lines = [line for line in (printed.out + printed.err).splitlines() if "drawing.drafting_precision" in line]
    if told is None:
        assert not lines
    else:
        (line,) = lines
        assert line.startswith(f"warning: drawing.drafting_precision: {precision:g} mm is outside what a ruler reads "
                               "(0.05 to 2 mm): ") and told in line and line.endswith("give 0.5 (a ruler read to half "
                                                                                     "a millimetre)")


@pytest.mark.parametrize(("kind", "name", "segment", "plan"), [
    ("velocity", "VB", "pb", "velocity"), ("velocity", "VE", "pe", "velocity"),
    ("velocity", "omega4", "pb", "velocity"), ("velocity", "ω4", "pb", "velocity"),  # ω4 = VB / lBC, C on the frame
    ("acceleration", "aB", "pb", "acceleration"), ("acceleration", "VB", "pb", "velocity")])
def test_a_value_typed_where_its_segment_was_asked_for_is_told_the_segment(kind, name, segment, plan):
    """VE = 0.758 (the value, in m/s) was answered "is not two letters of the plan": a student's slip deserves
    the segment to measure instead."""
    under = "" if kind == plan else f" under [measured.5] {plan}"
    with pytest.raises(SceneError) as caught:
        analyse(with_measured({5: {kind: {name: 0.758}}}))
    assert str(caught.value) == (f"measured.5.{kind}.{name}: {name} is the value, not a segment: give the segment "
                                 f"{segment}{under} it is read from, its length on the {plan} plan in mm")
