"""The scale a hand-drawn plan was laid off at, as the ``measured-far-off`` warning advises it: the advice must be the
value the student drew at, and following it must make readings exact at that value agree with the construction.

Every reading here is computed from the analytic motion (``graphplan.solve``), not from the program's plans: a plan
laid off with the driver's vector pa (or πa) at P mm has μ = |v_A| / P, so a segment of it is |v| · P / |v_A| mm.
"""

import dataclasses
import re

import pytest
from scene_texts import four_bar_through_a_toggle

import graphplan
from graphplan.analysis import analyse

FIXTURE = "fixtures/ratchet_crank_rocker.toml"
POSITION = 5  # numbered from 0: the motion's index 5
# Segment → the point (or the pair, B relative to A) whose velocity / acceleration it stands for.
SEGMENTS = {"pb": ("B",), "ab": ("B", "A"), "pe": ("E",), "ps3": ("S3",)}


def _magnitude(motion, attribute, points, index):
    values = [complex(*getattr(motion.point(name), attribute)[index]) for name in points]
    return abs(values[0] - values[1]) if len(values) == 2 else abs(values[0])


def readings_at(motion, kind, pole, index=POSITION, digits=2):
    """The segments of a plan laid off with the driver's vector at ``pole`` mm, read to 0.01 mm (``digits``)."""
    attribute = "v" if kind == "velocity" else "a"
    driver = _magnitude(motion, attribute, ("A",), index)
    return {name: round(_magnitude(motion, attribute, points, index) * pole / driver, digits)
            for name, points in SEGMENTS.items()}


def far_off(analysis):
    return [w for w in analysis.warnings if w.code == "measured-far-off"]


@pytest.mark.parametrize("kind", ["velocity", "acceleration"])
@pytest.mark.parametrize("pole", [120.0, 95.0, 180.0])
def test_a_plan_drawn_at_a_whole_pole_distance_is_advised_that_distance(kind, pole):
    """A plan drawn at exactly 120 mm was advised velocity_pole = 125 (the coarsest round step within 5 %), and
    every reading taken at 125 was 4 % off though the drawing had no error of its own."""
    scene = graphplan.load(FIXTURE)
    # The scene's plans at 60 mm: every reading well beyond the 15 % the warning needs.
    scene = dataclasses.replace(scene, drawing=dataclasses.replace(scene.drawing, **{f"{kind}_pole": 60.0}))
    readings = readings_at(graphplan.solve(scene), kind, pole)
    measured = dataclasses.replace(scene, measured={POSITION: {kind: readings}})
    (warning,) = far_off(analyse(measured))
    assert f"give `[drawing] {kind}_pole = {pole:g}`" in warning.detail, warning.detail
    within = float(re.search(r"every reading is within ([\d.]+) % of the plan", warning.detail)[1])
    assert within < 0.1
    # Following the advice: no warning, and every reading within 0.1 % of the plan as constructed.
    followed = dataclasses.replace(measured, drawing=dataclasses.replace(scene.drawing, **{f"{kind}_pole": pole}))
    analysis = analyse(followed)
    assert not far_off(analysis)
    plan = next(p for p in analysis.plans if p.number == POSITION)
    constructed = {row.quantity: row.plan for row in plan.errors if row.source == "construction"}
    measured_rows = [row for row in plan.errors if row.source == "measured"]
    assert len(measured_rows) >= len(SEGMENTS)
    for row in measured_rows:
        assert abs(row.plan / constructed[row.quantity] - 1.0) < 1e-3, row


@pytest.mark.parametrize("pole", [120.0, 95.0, 180.0])
def test_the_velocity_plans_of_every_position_drawn_at_a_whole_pole_are_advised_that_pole(pole):
    """The same rounding advised velocity_plans_pole = 125 for a grid plan drawn at 120 mm."""
    scene = graphplan.load(FIXTURE)
    scene = dataclasses.replace(scene, positions=dataclasses.replace(scene.positions, velocity_plans=tuple(range(12))),
                                drawing=dataclasses.replace(scene.drawing, velocity_plans_pole=60.0))
    readings = readings_at(graphplan.solve(scene), "velocity", pole, index=3)
    measured = dataclasses.replace(scene, measured={3: {"velocity": readings}})
    (warning,) = far_off(analyse(measured))
    assert f"give `[drawing] velocity_plans_pole = {pole:g}`" in warning.detail, warning.detail
    followed = dataclasses.replace(measured, drawing=dataclasses.replace(scene.drawing, velocity_plans_pole=pole))
    analysis = analyse(followed)
    assert not far_off(analysis)
    rows = [row for row in analysis.errors if row.position == 3 and row.source == "measured"]
    assert rows and all(abs(row.percent) < 0.1 for row in rows)


@pytest.mark.parametrize(("kind", "given", "told", "instead"), [
    ("velocity", {}, "`[drawing] velocity_scale = 1` (in place of velocity_pole)", "(вместо velocity_pole)"),
    ("acceleration", {"acceleration_pole": None, "acceleration_scale": 0.5}, "`[drawing] acceleration_scale = 1`",
     None),
])
def test_readings_that_agree_at_one_unit_a_millimetre_are_told_both_explanations(kind, given, told, instead):
    """An acceleration plan truly drawn at μa = 1 (m/s²)/mm (πa = |aA| mm) was told only "values typed in m/s²:
    give the millimetres", which turns correct readings wrong; the force polygons' message gives both."""
    from graphplan.report.tables import markdown

    scene = graphplan.load(FIXTURE)
    scene = dataclasses.replace(scene, drawing=dataclasses.replace(scene.drawing, **given))
    motion = graphplan.solve(scene)
    # At one unit a millimetre the driver's vector is |v_A| (|a_A|) mm long: the readings are the values themselves.
    driver = _magnitude(motion, "v" if kind == "velocity" else "a", ("A",), POSITION)
    readings = readings_at(motion, kind, driver)
    measured = dataclasses.replace(scene, measured={POSITION: {kind: readings}})
    (warning,) = far_off(analyse(measured))
    unit = "(m/s)/mm" if kind == "velocity" else "(m/s²)/mm"
    symbol = "μV" if kind == "velocity" else "μa"
    assert "give the millimetres measured" in warning.detail
    assert f"or, drawn at {symbol} = 1 {unit}, give {told}" in warning.detail, warning.detail
    russian = markdown(analyse(dataclasses.replace(measured, locale="ru")))
    assert f"или, если план построен в масштабе {symbol} = 1 {unit.replace('m/s', 'м/с').replace('mm', 'мм')}" in russian
    assert (instead or told) in russian
    # Taken at μ = 1 the readings agree with the construction.
    setting = {f"{kind}_pole": None, f"{kind}_scale": 1.0}
    followed = analyse(dataclasses.replace(measured, drawing=dataclasses.replace(scene.drawing, **setting)))
    assert not far_off(followed)
    rows = [row for row in followed.errors if row.position == POSITION and row.source == "measured"]
    assert rows and all(abs(row.percent) < 0.5 for row in rows)


# A four-bar whose coupler and rocker lie in one line at φ = 180° (|AC| = 0.2 + 1.0 = AB + BC = 1.2), position 7 of
# 12 numbered from 1: no plan can be drawn there.
TOGGLE = four_bar_through_a_toggle() + """
[positions]
count = 12
"""


@pytest.mark.parametrize(("positions", "plan"), [("plans = [2, 7]", "plan"),
                                                 ('plans = [2]\nvelocity_plans = "all"', "velocity plan")])
def test_readings_of_a_singular_plan_position_are_refused_by_check_and_run_alike(tmp_path, capsys, positions, plan):
    """The readings of a plan position that turned out singular were dropped without a word: `check` said "ok",
    and errors.md, results.json and the note had nothing for them, as if they had been checked."""
    from graphplan.cli import main

    scene = tmp_path / "toggle.toml"
    scene.write_text(TOGGLE + positions + "\n[measured.2]\nvelocity = { pb = 10.0 }\n"
                     "[measured.7]\nvelocity = { pb = 10.0, ab = 20.0 }\n", encoding="utf-8")
    told = []
    for command in (["check", str(scene)], ["run", str(scene), "--out", str(tmp_path / "out")]):
        assert main(command) != 0
        told.append(capsys.readouterr().err)
    assert told[0] == told[1]
    assert (f"measured.7: cannot be checked: position 7 is singular and has no {plan} to check the readings "
            "against (") in told[0]
    # Readings of the regular position alone are checked as before.
    scene.write_text(TOGGLE + positions + "\n[measured.2]\nvelocity = { pb = 10.0 }\n", encoding="utf-8")
    assert main(["check", str(scene)]) == 0


def _grid_scene(pole=60.0):
    scene = graphplan.load(FIXTURE)
    return dataclasses.replace(scene, positions=dataclasses.replace(scene.positions, velocity_plans=tuple(range(12))),
                               drawing=dataclasses.replace(scene.drawing, velocity_plans_pole=pole))


@pytest.mark.parametrize("grid", [True, False])
def test_a_key_that_sets_every_position_is_not_advised_from_one_position_alone(grid):
    """Position 3 measured at the scene's scale, position 4 off a plan drawn at pa = 95 mm: position 4 was told
    velocity_plans_pole = 95 without a word that the key sets position 3 too, whose readings it then put off (the
    advice went back and forth).  The same with velocity_pole for two plan-sheet positions."""
    from graphplan.report.tables import markdown

    if grid:
        scene, right, wrong, key = _grid_scene(60.0), 3, 4, "velocity_plans_pole"
    else:
        scene = graphplan.load(FIXTURE)
        scene = dataclasses.replace(scene, drawing=dataclasses.replace(scene.drawing, velocity_pole=60.0))
        right, wrong, key = 5, 11, "velocity_pole"
    motion = graphplan.solve(scene)
    # Read to 1e-6 mm: a short segment read to 0.01 mm is itself 0.1 % off.
    measured = {right: {"velocity": readings_at(motion, "velocity", 60.0, right, 6)},
                wrong: {"velocity": readings_at(motion, "velocity", 95.0, wrong, 6)}}
    analysis = analyse(dataclasses.replace(scene, measured=measured))
    (warning,) = far_off(analysis)
    assert warning.detail.startswith(f"measured.{wrong}: ")
    # Readings at 95 mm are lengths at 60 mm times 60 / 95.
    factor = 60.0 / 95.0
    assert f"give `[drawing] {key} = 95`" in warning.detail
    assert (f"but {key} sets the scale of position {right} too, whose readings fit the present scale and would then "
            f"be off: rather keep it and give the readings of position {wrong} times {factor:.4g}") in warning.detail
    russian = markdown(dataclasses.replace(analysis, scene=dataclasses.replace(analysis.scene, locale="ru")))
    assert (f"Но {key} задаёт масштаб и для положения {right}: замеры там согласуются с нынешним масштабом" in russian)
    assert f"замеры положения {wrong} умножьте на {f'{factor:.4g}'.replace('.', ',')}." in russian
    # Following that advice leaves both positions' readings within 0.1 % and warns of nothing.
    measured[wrong] = {"velocity": {name: mm * factor for name, mm in measured[wrong]["velocity"].items()}}
    followed = analyse(dataclasses.replace(scene, measured=measured))
    assert not far_off(followed)
    rows = [row for row in followed.errors if row.position in (right, wrong) and row.source == "measured"]
    assert {row.position for row in rows} == {right, wrong} and all(abs(row.percent) < 0.1 for row in rows)


def test_positions_all_drawn_at_one_other_scale_are_advised_the_key_without_a_caveat():
    scene = _grid_scene(60.0)
    motion = graphplan.solve(scene)
    measured = {number: {"velocity": readings_at(motion, "velocity", 120.0, number)} for number in (3, 4)}
    warnings = far_off(analyse(dataclasses.replace(scene, measured=measured)))
    assert len(warnings) == 2
    for warning in warnings:
        assert "give `[drawing] velocity_plans_pole = 120`" in warning.detail and "but " not in warning.detail


@pytest.mark.parametrize("kind", ["velocity", "acceleration"])
def test_a_uniform_scale_slip_under_the_far_off_threshold_is_named_as_such(kind):
    """Every reading exactly 1.1 times the construction (pa = 165 mm for the scene's 150, πa = 110 for 100) gave
    no warning: each row showed δ = −10 % as if the drawing were 10 % wrong everywhere, not laid off at another pole."""
    scene = graphplan.load(FIXTURE)
    given = getattr(scene.drawing, f"{kind}_pole")
    motion = graphplan.solve(scene)
    (warning,) = far_off(analyse(dataclasses.replace(scene, measured={
        POSITION: {kind: readings_at(motion, kind, given * 1.1)}})))
    assert f"every reading of the {kind} plan is 1.1 times the plan as constructed" in warning.detail
    assert f"give `[drawing] {kind}_pole = {given * 1.1:g}`" in warning.detail
    # A ratio within 5 % of one, or readings that scatter by more than the drafting precision, are a drawing's
    # own errors: nothing is said.
    assert not far_off(analyse(dataclasses.replace(scene, measured={
        POSITION: {kind: readings_at(motion, kind, given * 1.04)}})))
    scattered = {name: mm * (1.0 + (0.04 if index % 2 else -0.02))
                 for index, (name, mm) in enumerate(readings_at(motion, kind, given * 1.1).items())}
    assert not far_off(analyse(dataclasses.replace(scene, measured={POSITION: {kind: scattered}})))


def test_positions_drawn_at_two_other_scales_are_told_no_one_value_of_the_key_fits_both():
    """Position 3 drawn at pa = 95 mm and position 4 at 120 were told velocity_plans_pole = 95 and = 120, one key
    that cannot be both, and neither warning said so."""
    from graphplan.report.tables import markdown

    scene = _grid_scene(60.0)
    motion = graphplan.solve(scene)
    poles = {3: 95.0, 4: 120.0}
    measured = {number: {"velocity": readings_at(motion, "velocity", pole, number, 6)} for number, pole in poles.items()}
    analysis = analyse(dataclasses.replace(scene, measured=measured))
    warnings = {w.position: w.detail for w in far_off(analysis)}
    assert len(warnings) == 2
    for number, other in ((3, 4), (4, 3)):
        detail = next(d for d in warnings.values() if d.startswith(f"measured.{number}: "))
        assert f"give `[drawing] velocity_plans_pole = {poles[number]:g}`" in detail
        assert (f"but velocity_plans_pole sets the scale of position {other} too, whose readings ask "
                f"velocity_plans_pole = {poles[other]:g} (no one value fits them all): rather keep it and give the "
                f"readings of position {number} times {60.0 / poles[number]:.4g}") in detail
    russian = markdown(dataclasses.replace(analysis, scene=dataclasses.replace(analysis.scene, locale="ru")))
    assert "Но velocity_plans_pole задаёт масштаб и для положения 4, а замеры там требуют velocity_plans_pole = 120" in russian
