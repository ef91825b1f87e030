"""The reactions of the force polygons in the error tables: construction, drafting and a student's readings.

The reference is the other method: every equilibrium equation of the
mechanism solved at once (:mod:`graphplan.statics`), not the polygons.
"""

import dataclasses
import functools
import json
import math
from pathlib import Path

import pytest
from sheet_texts import flat

import graphplan
from graphplan.analysis import analyse
from graphplan.check import ErrorRow, force_error_rows
from graphplan.cli import main
from graphplan.errors import SceneError
from graphplan.forces import ForcePlan, Found
from graphplan.render.drawings import at_length_scale
from graphplan.report.tables import markdown

RATCHET = "fixtures/ratchet_crank_rocker.toml"
WITH_SLIDES = ("fixtures/quick_return_slotted_lever.toml", "fixtures/shaper_six_bar.toml",
               "fixtures/offset_slider_crank.toml", "fixtures/slider_driven.toml")


def force_rows(plan, source):
    return {row.quantity: row for row in plan.errors if row.source == source and row.quantity.startswith("R")}


def with_scene(path, drawing=None, measured=None):
    scene = graphplan.load(path)
    if drawing:
        scene = dataclasses.replace(scene, drawing=dataclasses.replace(scene.drawing, **drawing))
    if measured is not None:
        scene = dataclasses.replace(scene, measured=measured)
    return scene


@pytest.mark.parametrize("path", (RATCHET, *WITH_SLIDES))
def test_every_reaction_of_the_polygons_is_in_the_table_and_agrees_with_the_linear_system(path):
    analysis = analyse(graphplan.load(path))
    assert analysis.plans and all(plan.forces is not None for plan in analysis.plans)
    for plan in analysis.plans:
        rows = force_rows(plan, "construction")
        assert set(rows) == set(plan.forces.reactions)
        for name, row in rows.items():
            solved = analysis.equilibrium.reaction(name).force[plan.index]
            assert row.analytic == pytest.approx(abs(complex(solved)), rel=1e-12)
            assert abs(row.percent) < 1e-8, row


def polygon_vector(plan, name):
    back = f"R{name[2]}{name[1]}"
    for group in plan.forces.groups:
        vectors = {v.name: v.end - v.start for v in group.polygon.vectors}
        if vectors.get(name):
            return vectors[name]
        if f"{name}τ" in vectors or f"{name}n" in vectors:
            return vectors.get(f"{name}τ", 0j) + vectors.get(f"{name}n", 0j)
        if vectors.get(back):
            return -vectors[back]
    raise AssertionError(f"{name} is on no polygon")


def test_a_drafted_reaction_is_its_vector_on_the_polygon_rounded_to_the_precision():
    analysis = analyse(graphplan.load(RATCHET))
    plan = analysis.plans[0]
    precision = analysis.scene.drawing.drafting_precision
    rows = force_rows(plan, "drafting")
    changed = 0
    for name, found in plan.forces.reactions.items():
        # The reaction on the polygon of the group that finds it, at that polygon's μF: one vector, its τ and
        # n components joined, or the inner vector of the reaction back (R43 for R34).
        scale = next(group.scale for group in plan.forces.groups if any(f.name == name for f in group.found))
        millimetres = abs(polygon_vector(plan, name)) / scale
        assert rows[name].plan == pytest.approx(round(millimetres / precision) * precision * scale, rel=1e-12)
        changed += not math.isclose(rows[name].plan, abs(found.force), rel_tol=1e-9)
    assert changed  # rounding to 0.5 mm at μF moves at least one of them


def test_drafting_errors_of_the_reactions_shrink_with_the_precision():
    worst = []
    for precision in (2.0, 0.5, 0.1):
        analysis = analyse(with_scene(RATCHET, drawing={"drafting_precision": precision}))
        worst.append(max(abs(row.percent) for plan in analysis.plans
                         for row in force_rows(plan, "drafting").values()))
    assert worst == sorted(worst, reverse=True) and worst[-1] < worst[0] / 5


def test_a_students_force_readings_are_taken_at_the_scenes_force_scale():
    measured = {5: {"velocity": {"pb": 39.0}, "forces": {"R23": 52.5, "R12": 76.0}}}
    analysis = analyse(with_scene(RATCHET, drawing={"force_scale": 20.0}, measured=measured))
    plan = next(p for p in analysis.plans if p.number == 5)
    assert plan.forces.scale == 20.0
    rows = force_rows(plan, "measured")
    assert set(rows) == {"R23", "R12"}
    for name, millimetres in measured[5]["forces"].items():
        exact = abs(complex(analysis.equilibrium.reaction(name).force[plan.index]))
        assert rows[name].plan == pytest.approx(millimetres * 20.0)
        assert rows[name].percent == pytest.approx((exact - millimetres * 20.0) / exact * 100.0)
    # The velocity reading of the same position still gives its row.
    assert any(row.source == "measured" and row.quantity == "VB" for row in plan.errors)


def test_a_given_force_scale_draws_every_polygon_at_it(tmp_path):
    text = Path(RATCHET).read_text(encoding="utf-8").replace("sheet = \"A1\"", "sheet = \"A1\"\nforce_scale = 25.0")
    assert "force_scale = 25.0" in text
    scene = tmp_path / "scene.toml"
    scene.write_text(text, encoding="utf-8")
    # Only the force drawings, which are read here (with results.json, which every run writes).
    assert main(["run", str(scene), "--out", str(tmp_path / "out"), "--only", "forces"]) == 0
    document = json.loads((tmp_path / "out" / "results.json").read_text(encoding="utf-8"))
    with_forces = [p for p in document["positions"] if "forces" in p]
    assert with_forces and {p["forces"]["polygon_scale"] for p in with_forces} == {25.0}
    for position in with_forces:
        drawing = flat((tmp_path / "out" / f"forces_{position['index']}.svg").read_text(encoding="utf-8"))
        assert "μF = 25 Н/мм" in drawing
    reactions = {row["quantity"] for row in document["errors"] if row["quantity"].startswith("R")}
    assert reactions == {"R12", "R14", "R23", "R34"}


def test_a_reading_of_a_reaction_the_polygons_do_not_have_names_them():
    scene = with_scene(RATCHET, measured={5: {"forces": {"R99": 10.0}}})
    with pytest.raises(SceneError) as caught:
        analyse(scene)
    assert str(caught.value) == ("measured.5.forces.R99: the force polygons have no reaction R99; "
                                 "they have R23, R14, R34, R12")


def test_force_readings_without_a_force_analysis_are_refused(tmp_path):
    text = Path(RATCHET).read_text(encoding="utf-8")
    start, end = text.index("[links.2]"), text.index("[positions]")
    text = text[:start] + text[end:] + "\n[measured.11]\nforces = { R23 = 30.0 }\n"
    scene = tmp_path / "scene.toml"
    scene.write_text(text, encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out)]) != 0
    assert not out.exists()
    with pytest.raises(SceneError, match=r"^measured\.11\.forces: the scene has no force analysis"):
        analyse(graphplan.load(scene))


def test_a_reaction_that_vanishes_is_zero_in_both_solutions():
    # Rounding leaves 1e-13 N where the linear system gives 1e-14 N: both are zero, not a 900 % error.
    plan = ForcePlan(groups=(), reactions={"R12": Found("R12", "A", 1, 2, 1e-13 + 0j),
                                           "R23": Found("R23", "B", 2, 3, 400.0 + 300.0j)},
                     balancing=0.0, scale=10.0)
    rows = force_error_rows(3, {"R12": 1e-14 + 0j, "R23": 400.0 + 300.0j}, plan, 0.5)
    assert ErrorRow(3, "R12", 0.0, 0.0, "construction") in rows
    assert ErrorRow(3, "R12", 0.0, 0.0, "drafting") in rows
    assert ErrorRow(3, "R23", 500.0, 500.0, "drafting") in rows


def test_the_error_report_explains_the_reaction_rows_only_when_it_has_them():
    with_forces = markdown(analyse(graphplan.load(RATCHET)))
    assert "Реакции R, Н" in with_forces and "| R23 |" in with_forces
    scene = graphplan.load(RATCHET)
    kinematics_only = dataclasses.replace(scene, links={}, loads=())
    text = markdown(analyse(kinematics_only))
    assert "Реакции R" not in text and "| R23 |" not in text


def drawn_length(plan, name):
    """The length (mm) of the vector ``name`` on the polygon that draws it, and that polygon's μF."""
    for group in plan.forces.groups:
        for vector in group.polygon.vectors:
            if vector.name == name:
                return abs(vector.end - vector.start) / group.scale, group.scale
    raise AssertionError(f"no polygon draws {name}")


def test_a_reading_of_a_reaction_by_the_name_its_polygon_draws_it_under_is_of_the_reaction_reversed():
    # The ratchet's polygons draw R43 (group II closes on link 3 with link 4's force on it) and the crank's R32
    # (laid off, found by group II as R23): a student reads them there, each at its own polygon's μF.
    analysis = analyse(graphplan.load(RATCHET))
    plan = next(p for p in analysis.plans if p.number == 5)
    r43, r43_scale = drawn_length(plan, "R43")
    r32, r32_scale = drawn_length(plan, "R32")
    assert r32_scale != plan.forces.scale_of("R23")  # the crank's polygon is drawn at a μF of its own
    measured = {5: {"forces": {"R43": round(r43 * 1.02, 1), "R32": round(r32 * 0.97, 1)}}}
    plan = next(p for p in analyse(with_scene(RATCHET, measured=measured)).plans if p.number == 5)
    rows = force_rows(plan, "measured")
    assert set(rows) == {"R34", "R23"}
    for reaction, (reading, scale) in {"R34": (measured[5]["forces"]["R43"], r43_scale),
                                       "R23": (measured[5]["forces"]["R32"], r32_scale)}.items():
        exact = abs(complex(analysis.equilibrium.reaction(reaction).force[plan.index]))
        assert rows[reaction].plan == pytest.approx(reading * scale)
        assert rows[reaction].percent == pytest.approx((exact - reading * scale) / exact * 100.0)


def test_a_reaction_read_both_ways_round_is_refused():
    scene = with_scene(RATCHET, measured={5: {"forces": {"R34": 50.0, "R43": 52.0}}})
    with pytest.raises(SceneError, match=r"^measured\.5\.forces\.R43: measures the reaction R34 measures"):
        analyse(scene)


def test_the_reactions_table_signs_its_errors_as_the_error_tables_do():
    # Both write δ = (exact − found)/exact: a polygon's reaction 2 % short is +2 % in both.
    from graphplan.report.forces import error_percent

    row = ErrorRow(5, "R23", 100.0, 98.0, "construction")
    assert row.percent == pytest.approx(2.0)
    assert error_percent(100.0, 98.0) == "2"
    assert error_percent(0.0, 0.0) == "0" and error_percent(0.0, 1.0) == "—"


def exact_millimetres(analysis, number, scale):
    """The ratchet's reactions at position ``number`` from the linear system (not the polygons), in mm at μF ``scale``:
    what a student reads off polygons drawn with care at that μF."""
    index = next(p.index for p in analysis.plans if p.number == number)
    return {name: abs(complex(analysis.equilibrium.reaction(name).force[index])) / scale
            for name in ("R23", "R12", "R34", "R14")}


def far_off(analysis):
    (warning,) = [w for w in analysis.warnings if w.code == "measured-far-off"]
    return warning.detail


def test_force_polygons_all_drawn_at_another_scale_are_named_as_such_with_the_key_to_give():
    """Every reaction read off polygons drawn at 10 N/mm where the scene says force_scale = 20 was called a
    100 % misread length; the plans' readings in one ratio were already told as a plan at another scale."""
    plain = analyse(graphplan.load(RATCHET))
    readings = {5: {"forces": exact_millimetres(plain, 5, 10.0)}}
    analysis = analyse(with_scene(RATCHET, drawing={"force_scale": 20.0}, measured=readings))
    detail = far_off(analysis)
    assert "misread" not in detail
    assert "every reading of the force polygons fits polygons drawn at μF = 10 N/mm" in detail
    assert "not the μF they were read at (20 N/mm): give `[drawing] force_scale = 10`" in detail
    assert "within 0.0 % of the polygons as constructed" in detail
    text = markdown(dataclasses.replace(analysis, scene=dataclasses.replace(analysis.scene, locale="en")))
    assert "Every reading of the force polygons fits polygons drawn at μF = 10 N/mm" in text


def test_polygons_each_at_the_programs_own_scale_read_off_a_drawing_at_one_are_told_the_one_scale():
    """Without force_scale each group's polygon has its own μF, which a student cannot guess: readings of polygons
    all drawn at 20 N/mm showed II(3,4)'s as 50 % misread."""
    plain = analyse(graphplan.load(RATCHET))
    scales = next(p for p in plain.plans if p.number == 5).forces.group_scales
    assert scales["II(3,4)"] != 20.0 and 20.0 in scales.values()
    analysis = analyse(with_scene(RATCHET, measured={5: {"forces": exact_millimetres(plain, 5, 20.0)}}))
    detail = far_off(analysis)
    assert "misread" not in detail and "give `[drawing] force_scale = 20`" in detail
    assert f"II(3,4) {scales['II(3,4)']:g}" in detail


def test_one_polygon_at_another_scale_is_told_apart_from_a_misread_reaction_of_another():
    plain = analyse(graphplan.load(RATCHET))
    scales = next(p for p in plain.plans if p.number == 5).forces.group_scales
    at = exact_millimetres(plain, 5, scales["II(3,4)"] / 2.0)  # group II's polygon drawn twice as large
    at["R12"] = exact_millimetres(plain, 5, scales["I(1,2)"])["R12"] * 1.5  # the crank's reaction misread
    detail = far_off(analyse(with_scene(RATCHET, measured={5: {"forces": at}})))
    assert f"every reading of the force polygon II(3,4) fits polygons drawn at μF = {scales['II(3,4)'] / 2:g}" in detail
    assert "R12 = " in detail.split("misread")[0].split("readings more than")[1]
    assert "R23 = " not in detail.split("readings more than")[1]


def test_reactions_typed_in_newtons_are_named_as_such():
    plain = analyse(graphplan.load(RATCHET))
    newtons = exact_millimetres(plain, 5, 1.0)
    detail = far_off(analyse(with_scene(RATCHET, measured={5: {"forces": newtons}})))
    assert "is the force it stands for, in N, not its length on the polygon" in detail and "misread" not in detail


@pytest.mark.parametrize(("reading", "part", "whole"), [("R23n", "normal", "R23"), ("R14τ", "tangential", "R14"),
                                                        ("R23t", "tangential", "R23"), ("R32t", "tangential", "R23")])
def test_a_reading_of_a_reactions_component_says_it_is_one_and_which_whole_reaction_to_give(reading, part, whole):
    """The force sheet letters R23n and R23τ on group II's polygon: "the force polygons have no reaction R23n" read
    as a misspelt name, not as "components are not checked"."""
    plan = next(p for p in analyse(graphplan.load(RATCHET)).plans if p.number == 5)
    (group,) = [g for g in plan.forces.groups if any(v.name == "R23τ" for v in g.polygon.vectors)]
    with pytest.raises(SceneError) as caught:
        analyse(with_scene(RATCHET, measured={5: {"forces": {reading: 50.0}}}))
    assert str(caught.value).startswith(
        f"measured.5.forces.{reading}: {reading} is the {part} component of {reading[:3]} on the polygon of "
        f"{group.label}, laid off to find it and not checked: give the whole reaction {whole} (lettered on that "
        "polygon beside its components); the polygons find R23, R14, R34, R12")


@functools.cache
def _shaper_starter():
    """The shaper's starter analysed once for both cases that read its reactions."""
    from graphplan.starters import starter

    return analyse(graphplan.scene.loads(starter("shaper")))


@pytest.mark.parametrize("drawn_with_friction", [True, False])
def test_with_friction_the_errors_say_which_polygons_the_readings_are_checked_against(drawn_with_friction):
    """The shaper's friction sheet prints R45 = 2123 N; read off it, errors.md showed −1.8 % against the polygons
    without friction and never said which polygons the readings were checked against."""
    from graphplan.report.note import note_markdown
    from graphplan.starters import starter

    plain = _shaper_starter()
    plan = next(p for p in plain.plans if p.number == 3)
    balance = plain.with_friction if drawn_with_friction else plain.equilibrium  # the linear systems, not the polygons
    reaction = abs(complex(balance.reaction("R45").force[plan.index]))
    millimetres = round(reaction / plan.forces.scale_of("R45"), 1)
    analysis = analyse(graphplan.scene.loads(starter("shaper") + f"\n[measured.3]\nforces = {{ R45 = {millimetres} }}\n"))
    # The note states μl among its data: at the μl a run chooses for the starter on its A1 (0.004 m/mm), not
    # chosen again, which lays every sheet out at each μl tried (three quarters of the test); no sentence read
    # here depends on it.
    analysis = at_length_scale(analysis, 0.004)
    errors, note = markdown(analysis), note_markdown(analysis)
    assert "these are the polygons without friction (forces_N.svg), and the reactions measured on the hand-drawn " \
           "polygons ([measured] forces) are checked against them" in errors
    assert ("Every reading of a reaction stands nearer the polygons with friction (forces_friction_3.svg: R45 = "
            in errors) is drawn_with_friction
    # The note's reader has the figures, not the run's files: the polygons are named in words.
    assert "these are the force polygons without friction, and the reactions measured on the hand-drawn polygons " \
           "are checked against them" in note
    assert ("Every reading of a reaction stands nearer the polygons with friction (R45 = " in note) is drawn_with_friction
