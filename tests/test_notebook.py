"""The Python interface for notebooks: scene.solve(), scene.plan(n), drawings that show themselves."""

from __future__ import annotations

import dataclasses
import json
import re
from pathlib import Path
from types import MappingProxyType
from xml.etree import ElementTree

import numpy as np
import pytest
from sheet_texts import flat

import graphplan
from graphplan.analysis import analyse

RATCHET = "fixtures/ratchet_crank_rocker.toml"


@pytest.fixture(scope="module")
def scene():
    return graphplan.load(RATCHET)


def test_solve_is_the_module_solve(scene):
    here, there = scene.solve(), graphplan.solve(scene)
    np.testing.assert_array_equal(here.link(4).omega, there.link(4).omega)
    dense = scene.solve(driver=np.radians([10.0, 20.0]))
    assert dense.point("B").r.shape == (2, 2)


def test_a_listed_position_gives_the_plans_of_the_run(scene):
    """Position 5 is listed in the scene: its notebook plans read what the run's plans read."""
    five = scene.plan(5)
    run = next(plan for plan in analyse(scene).plans if plan.number == 5)
    assert five.number == 5
    assert five.velocity.scale == run.velocity.scale
    for reading in run.readings:
        assert five.values[reading.quantity] == pytest.approx(reading.value(run.plans), rel=1e-12)
    # The values read off the plans are the motion's: VB against the analytic speed of B.
    assert five.values["VB"] == pytest.approx(float(np.hypot(*scene.solve().point("B").v[5])), rel=1e-9)


def test_an_unlisted_position_is_planned_too(scene):
    three = scene.plan(3)
    assert three.values["VB"] == pytest.approx(float(np.hypot(*scene.solve().point("B").v[3])), rel=1e-9)
    assert three.forces is not None


def test_a_position_shows_itself_as_its_plan_sheet(scene, tmp_path):
    three = scene.plan(3)
    svg = three._repr_svg_()
    root = ElementTree.fromstring(svg)
    assert root.tag.endswith("svg")
    assert any((element.get("id") or "").startswith("velocity") for element in root.iter())
    assert three.forces_drawing._repr_svg_().startswith("<?xml") or "<svg" in three.forces_drawing.svg
    saved = three.drawing.save(tmp_path / "three.svg")
    assert saved.read_text(encoding="utf-8") == svg


def test_no_such_position(scene):
    # A GraphplanError, as the README promises of bad input (a plain ValueError escaped `except GraphplanError`).
    with pytest.raises(graphplan.GraphplanError, match="^positions: no position 12: the scene numbers its positions "
                                                      "0 to 11$"):
        scene.plan(12)


def test_a_position_with_friction_shows_its_sheet_with_friction(scene):
    import dataclasses

    from graphplan.notebook import plan
    from graphplan.scene import FrictionSpec

    assert scene.plan(3).forces_with_friction_drawing is None  # the scene has no [[friction]]
    rubbing = dataclasses.replace(scene, friction=(FrictionSpec("friction[0]", "O", None, 0.1, 0.02, None),))
    svg = plan(rubbing, 3).forces_with_friction_drawing.svg
    root = ElementTree.fromstring(svg)
    assert any((element.get("id") or "").endswith("-friction") for element in root.iter())


def test_hand_readings_of_a_position_drawn_only_among_the_velocity_plans_are_read_at_their_scale(scene):
    """A student who drew a position only among the velocity plans of every position measured it there, at their
    μV; scene.plan(n) draws a plan sheet at another μV and read the readings at that one (40 % off where the
    run's error table said 0.7 %)."""
    first, count = scene.positions.number_from, scene.positions.count
    speeds = np.hypot(*scene.solve().point("B").v.T)
    # A position between the extremes (at an extreme B stands still and a percentage of it means nothing).
    number = next(n for n in range(first, first + count) if n not in scene.positions.plans and speeds[n - first] > 0.1)
    grid_scene = dataclasses.replace(scene, positions=dataclasses.replace(scene.positions,
                                                                          velocity_plans=tuple(range(first, first + count))))
    grid = next(position for position in analyse(grid_scene).velocity_plans if position.number == number)
    exact = float(speeds[number - first])
    drawn = 1.02 * exact / grid.velocity.scale  # a reading 2 % long, on the plan drawn at the grid's μV
    measured = dataclasses.replace(grid_scene, measured=MappingProxyType(
        {number: MappingProxyType({"velocity": MappingProxyType({"pb": drawn})})}))
    planned = measured.plan(number)
    assert planned.velocity.scale != pytest.approx(grid.velocity.scale)  # the plan sheet is at another μV
    [row] = [row for row in planned.errors if row.source == "measured" and row.quantity == "VB"]
    assert row.plan == pytest.approx(1.02 * exact, rel=1e-9)
    assert row.percent == pytest.approx(-2.0, rel=1e-6)


def test_a_position_s_plan_sheet_is_the_run_s_at_the_mu_l_the_run_chooses(tmp_path):
    """The Russian shaper leaves μl to the program, which takes the one that lays the run's drawings (positions 3
    and 10) on the fewest sheets, 0.004 m/mm; the notebook chose it for position 3 alone and drew 0.005."""
    from graphplan.cli import main
    from graphplan.starters import starter

    path = tmp_path / "shaper.toml"
    path.write_text(starter("shaper", "ru"), encoding="utf-8")
    assert main(["run", str(path), "--out", str(tmp_path / "run"), "--only", "velocity,acceleration"]) == 0
    written = (tmp_path / "run" / "plan_3.svg").read_text(encoding="utf-8")
    assert "μl = 0,004 м/мм" in flat(written)
    assert graphplan.load(path).plan(3).drawing.svg == written


def test_the_positions_of_one_scene_share_the_run_s_choice_of_mu_l(monkeypatch):
    """Each plan(n).drawing chose the run's μl again, laying every plan position's sheets out at a few μl (2 to 4 s
    a drawing on the shaper): a scene's positions now choose it once, and a changed scene chooses afresh."""
    from graphplan.render import sheet

    chosen = []
    choose = sheet.fewest_sheets_length_scale
    monkeypatch.setattr(sheet, "fewest_sheets_length_scale", lambda *given: chosen.append(given) or choose(*given))
    ratchet = graphplan.load(RATCHET)
    left = dataclasses.replace(ratchet, drawing=dataclasses.replace(ratchet.drawing, length_scale=None))
    first, again = left.plan(5).drawing.svg, left.plan(5).drawing.svg
    assert first == again
    assert "μl" in flat(left.plan(2).drawing.svg)
    assert len(chosen) == 1
    assert "μl" in flat(dataclasses.replace(left, title="Another").plan(5).drawing.svg)
    assert len(chosen) == 2



@pytest.fixture(scope="module")
def rotor_path(tmp_path_factory):
    """The starter rotor: masses to balance in two planes, and the machine that carries it on its mounts."""
    from graphplan.starters import starter

    path = tmp_path_factory.mktemp("rotor") / "rotor.toml"
    path.write_text(starter("rotor"), encoding="utf-8")
    return path


@pytest.fixture(scope="module")
def rotor_run(rotor_path):
    """The folder the command line's run of the rotor writes."""
    from graphplan.cli import main

    folder = rotor_path.parent / "run"
    assert main(["run", str(rotor_path), "--out", str(folder)]) == 0
    return folder


def test_a_rotor_s_balancing_from_python_is_the_run_s(rotor_path, rotor_run):
    balancing = graphplan.load(rotor_path).balance()
    written = json.loads((rotor_run / "results.json").read_text(encoding="utf-8"))
    assert balancing.results == written["balancing"]
    assert balancing.drawing.svg == (rotor_run / "rotor_balancing.svg").read_text(encoding="utf-8")
    assert balancing._repr_svg_() == balancing.drawing.svg
    # The corrections by the two equilibrium equations solved at once, not by the polygons: Σ m·r = 0 and
    # Σ m·r·z = 0 with the corrections in planes L (z = 0.04 m) and R (z = 0.22 m).
    masses = [(18.0, 0.05, 0.0, 0.0), (14.0, 0.06, -60.0, 0.08), (10.0, 0.04, 135.0, 0.16)]
    unbalance = [m * r * np.exp(1j * np.radians(angle)) for m, r, angle, _ in masses]
    moment = sum(u * z for u, (*_, z) in zip(unbalance, masses, strict=True))
    left, right = np.linalg.solve([[1.0, 1.0], [0.04, 0.22]], [-sum(unbalance), -moment])
    for plane, correction in zip(balancing.planes, (left, right), strict=True):
        assert plane.mass_radius == pytest.approx(abs(correction), rel=1e-12)
        assert plane.angle_deg == pytest.approx(np.degrees(np.angle(correction)) % 360.0, abs=1e-9)
        assert plane.mass == pytest.approx(abs(correction) / 0.05, rel=1e-12)
    assert repr(balancing).startswith("<RotorBalancing of 'Rotor of a fan on its mounts': plane L: 1.413 kg·m at ")


def test_a_machine_s_vibration_from_python_is_the_run_s(rotor_path, rotor_run):
    shaking = graphplan.load(rotor_path).vibration_response()
    written = json.loads((rotor_run / "results.json").read_text(encoding="utf-8"))
    assert shaking.results == written["vibration"]
    for plot in ("magnification", "transmissibility"):
        assert getattr(shaking, f"{plot}_plot").svg == (rotor_run / f"vibration_{plot}.svg").read_text(encoding="utf-8")
    # X = m·e·ω²/√((k − M·ω²)² + (c·ω)²), TR = √(k² + (c·ω)²)/√(...) with c = 2·ζ·√(k·M).
    mass, unbalance, stiffness, omega = 100.0, 0.02, 1.0e5, 600.0 * 2.0 * np.pi / 60.0
    damping = 2.0 * 0.1 * np.sqrt(stiffness * mass)
    across = np.hypot(stiffness - mass * omega ** 2, damping * omega)
    assert shaking.response.amplitude == pytest.approx(unbalance * omega ** 2 / across, rel=1e-12)
    assert shaking.response.transmissibility == pytest.approx(np.hypot(stiffness, damping * omega) / across,
                                                              rel=1e-12)
    assert shaking.results["phase_deg"] == pytest.approx(
        np.degrees(np.arctan2(damping * omega, stiffness - mass * omega ** 2)), rel=1e-11)


def test_a_scene_s_run_written_from_python_is_the_command_line_s(rotor_path, rotor_run, tmp_path):
    done = graphplan.load(rotor_path).write(tmp_path / "from-python")
    assert sorted(path.name for path in done.files) == sorted(path.name for path in rotor_run.iterdir()
                                                               if path.name != ".graphplan-written")
    for path in done.files:
        assert path.read_bytes() == (rotor_run / path.name).read_bytes(), path.name
    assert done.warnings == ()
    assert repr(done).startswith(f"<Run of 'Rotor of a fan on its mounts': {len(done.files)} files in ")


def test_a_run_written_from_python_refuses_what_the_command_line_refuses_and_leaves_no_folder(rotor_path, tmp_path):
    from graphplan.errors import OutputError

    scene = graphplan.load(rotor_path)
    with pytest.raises(graphplan.SceneError, match=r"^only\[0\]: 'forces' needs a mechanism"):
        scene.write(tmp_path / "none", only=["forces"])
    with pytest.raises(graphplan.SceneError, match=r"^formats\[1\]: "):
        scene.write(tmp_path / "none", formats=["svg", "bmp"])
    with pytest.raises(graphplan.SceneError, match=r"^sheet: "):
        scene.write(tmp_path / "none", sheet="A0")
    with pytest.raises(TypeError, match=r"^formats is a list of names: formats=\['png'\], not formats='png'$"):
        scene.write(tmp_path / "none", formats="png")
    assert not (tmp_path / "none").exists()
    theirs = tmp_path / "theirs"
    theirs.mkdir()
    (theirs / "note.md").write_text("my own note", encoding="utf-8")
    with pytest.raises(OutputError, match=r"holds note\.md, .*move it away, or give scene\.write\(\) another folder$"):
        scene.write(theirs)
    assert [path.name for path in theirs.iterdir()] == ["note.md"]


def test_a_scene_asked_for_what_it_has_not_says_what_it_lacks_and_what_to_call(rotor_path, scene):
    rotor = graphplan.load(rotor_path)
    for verb in ("analyse", "solve"):
        with pytest.raises(graphplan.SceneError, match=r"^driver: is required but missing: the scene has no mechanism "
                                                       r"\(\[frame\] and \[driver\]\); for its \[balancing\] call "
                                                       r"scene\.balance\(\), for its \[vibration\] call "
                                                       r"scene\.vibration_response\(\)$"):
            getattr(rotor, verb)()
    with pytest.raises(graphplan.SceneError, match=r"^driver: .*scene\.balance\(\)"):
        rotor.plan(1)
    with pytest.raises(graphplan.SceneError, match=r"^driver: .*scene\.balance\(\)"):
        graphplan.solve(rotor)
    for verb, table in (("balance", "balancing"), ("vibration_response", "vibration"),
                        ("machine_dynamics", "dynamics")):
        with pytest.raises(graphplan.SceneError, match=rf"^{table}: the scene has no \[{table}\] table; for its "
                                                       r"mechanism call scene\.analyse\(\)$"):
            getattr(scene, verb)()


def test_a_linkage_s_rotor_and_vibration_are_worked_out_from_python_too(rotor_path, tmp_path):
    """A course project's mechanism with its rotor: the Analysis is the mechanism's, the scene balances the rotor."""
    import tomllib

    tables = tomllib.loads(Path(RATCHET).read_text(encoding="utf-8"))
    machine = tomllib.loads(rotor_path.read_text(encoding="utf-8"))
    tables.update(balancing=machine["balancing"], vibration=machine["vibration"])
    both = graphplan.load(tables)
    done = both.write(tmp_path / "run", only=["balancing", "vibration"])
    written = json.loads((done.folder / "results.json").read_text(encoding="utf-8"))
    assert both.balance().results == written["balancing"]
    assert both.vibration_response().results == written["vibration"]
    assert both.balance().results == graphplan.load(rotor_path).balance().results


def test_a_rotor_balanced_already_shows_its_corrections_without_an_angle():
    """Two masses in one plane whose m·r cancel: each plane's correction is zero, its angle undefined (None), and
    the notebook's line writes it —, as the drawing does (it raised formatting None)."""
    rotor = graphplan.load_text("""
[balancing]
masses = [ { mass = 2.0, radius = 0.1, angle = 0.0, plane = 0.1 },
           { mass = 4.0, radius = 0.05, angle = 180.0, plane = 0.1 } ]
planes = [0.0, 0.2]
""").balance()
    assert [plane.angle_deg for plane in rotor.planes] == [None, None]
    assert repr(rotor).count(" kg·m at —") == 2


def test_a_value_the_plans_do_not_give_is_told_with_those_they_do(scene):
    """five.values["omega_4"] gave a bare KeyError('omega_4'); the scene's keys are told with the names they may
    be and the nearest."""
    values = scene.plan(5).values
    assert values["omega4"] == dict(values)["omega4"]
    with pytest.raises(KeyError) as missing:
        values["omega_4"]
    told = missing.value.args[0]
    assert told.startswith("'omega_4' is no value of the plans, which give ") and told.endswith(
        "; did you mean 'omega4'?")
    assert all(name in told for name in values)
    assert values.get("omega_4") is None and "omega_4" not in values


def test_a_reaction_the_force_analysis_does_not_find_is_told_with_those_it_does(scene):
    """forces.reactions["R32"] gave a bare KeyError('R32'), the values beside it their names; a name typed in
    Cyrillic letters is told which letter is which."""
    import copy
    import pickle

    reactions = scene.plan(5).forces.reactions
    assert reactions["R23"].force == dict(reactions)["R23"].force
    with pytest.raises(KeyError) as missing:
        reactions["R32"]
    told = missing.value.args[0]
    # R32 is R23 the other way round, not R34, which is nearer in spelling.
    assert told.startswith("'R32' is no reaction the force analysis finds, which finds ")
    assert told.endswith("; did you mean 'R23' (R32 = −R23)?")
    assert all(name in told for name in reactions)
    with pytest.raises(KeyError, match="Cyrillic"):
        scene.plan(5).values["VВ"]
    # As the error tables print them, or in another case.
    for typed, meant in (("ω4", "omega4"), ("ε3", "epsilon3"), ("vb", "VB"), ("r23", "R23")):
        values = reactions if typed.startswith("r") else scene.plan(5).values
        with pytest.raises(KeyError, match=f"did you mean '{meant}'"):
            values[typed]
    for kept in (copy.deepcopy(reactions), pickle.loads(pickle.dumps(reactions))):
        assert kept.keys() == reactions.keys()
        with pytest.raises(KeyError, match="is no reaction"):
            kept["R32"]


def test_each_plan_alone_is_a_drawing_for_a_report(scene):
    """A report's figure of the velocity plan had to be cut out of the plan sheet by hand: each plan is now a
    drawing of its own, under its caption, with no mechanism (no μl) and not the other plan."""
    five = scene.plan(5)
    velocity, acceleration = flat(five.velocity_drawing.svg), flat(five.acceleration_drawing.svg)
    assert "μV" in velocity and "μa" not in velocity and "μl" not in velocity
    assert "μa" in acceleration and "μV" not in acceleration and "μl" not in acceleration
    sheet = flat(five.drawing.svg)
    # The captions' scales are the plan sheet's own.
    for part, symbol in ((velocity, "μV"), (acceleration, "μa")):
        [scale] = re.findall(f"{symbol} = [^<]+", part)
        assert scale in sheet
