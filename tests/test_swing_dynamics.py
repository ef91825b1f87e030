"""The equivalent model of a machine whose driver rocks over a swing (fixtures/double_rocker_swing.toml).

A hand lever raised from 20° to 65° drives a double rocker against 20 N·m on its output rocker. The
model is checked against the two definitions worked out independently, by central differences of the
positions the analytic solution gives (no velocity of the solver enters):

- Je(φ) = Σ [m·|drS/dφ|² + JS·(dθ/dφ)²], the kinetic energy kept (per ½ω1²);
- Mr(φ) = Σ −m·g·dyS/dφ − 20·|dθ4/dφ|, the power of the weights and of a resistance that always
  opposes the rocker's motion (per ω1).

The driving moment is taken constant so that its work over the swing balances the resistances'
(the scene has no driving load): Md = Ar/Δφ, with Ar the trapezoid rule's integral of the differences
over 20 000 steps (converged to 10⁻⁸; the 90 steps of the model's own sampling left 2·10⁻⁴).
A swing is run once, so [dynamics] gives no flywheel and no equation of motion: their keys are refused.
"""

from __future__ import annotations

import json
import math
import re
from pathlib import Path

import numpy as np
import pytest

import graphplan
from graphplan.cli import main
from graphplan.dynamics import equivalent_model_of
from graphplan.errors import SceneError
from graphplan.scene import loads

ROOT = Path(__file__).resolve().parent.parent
FIXTURE = ROOT / "fixtures" / "double_rocker_swing.toml"
SLIDER = ROOT / "fixtures" / "slider_driven.toml"
SAMPLES = 90
GRAVITY = 9.81
RESISTANCE = 20.0   # N·m on link 4, always against its motion
STEP = 1e-6          # rad, of the central differences


def with_dynamics(path: Path, table: str = "") -> str:
    return path.read_text(encoding="utf-8") + f"\n[dynamics]\ncount = {SAMPLES}\n{table}"


@pytest.fixture(scope="module")
def scene():
    return loads(with_dynamics(FIXTURE))


@pytest.fixture(scope="module")
def model(scene):
    return equivalent_model_of(scene, SAMPLES)


def differences(scene, angles):
    """d/dφ of the centres' positions and of the links' angles, by central differences of the positions."""
    ahead = graphplan.solve(scene, driver=angles + STEP)
    behind = graphplan.solve(scene, driver=angles - STEP)
    centres = {number: link.centre for number, link in scene.links.items()}
    rates = {number: (ahead.point(centre).r - behind.point(centre).r) / (2 * STEP) for number, centre in centres.items()}
    turns = {number: np.unwrap(ahead.link(number).angle - behind.link(number).angle) / (2 * STEP)
             for number in centres}
    return rates, turns


def test_the_samples_run_once_over_the_swing_in_the_lever_s_direction(model):
    assert model.turning and not model.cyclic
    assert np.degrees(model.driver[[0, -1]]) == pytest.approx([20.0, 65.0], abs=1e-9)
    assert model.coordinate[-1] == pytest.approx(math.radians(45.0), rel=1e-12)


def test_the_reduced_inertia_keeps_the_kinetic_energy_of_the_links(scene, model):
    rates, turns = differences(scene, model.driver)
    expected = sum(scene.links[n].mass * np.sum(rates[n] ** 2, axis=1) + scene.links[n].inertia * turns[n] ** 2
                   for n in scene.links)
    assert model.inertia == pytest.approx(expected, rel=1e-6)


def test_the_reduced_resistance_keeps_the_power_of_the_weights_and_of_the_rocker_s_load(scene, model):
    rates, turns = differences(scene, model.driver)
    weights = sum(-scene.links[n].mass * GRAVITY * rates[n][:, 1] for n in scene.links)
    expected = weights - RESISTANCE * np.abs(turns[4])
    assert model.resisting == pytest.approx(expected, rel=1e-6, abs=1e-9)
    # The rocker turns back within the swing, where the load turns against its new motion: Mr has a kink.
    assert np.any(turns[4] > 0) and np.any(turns[4] < 0)


def test_the_driving_moment_is_constant_and_balances_the_work_over_the_swing(scene, model):
    angles = np.linspace(model.driver[0], model.driver[-1], 20_001)
    rates, turns = differences(scene, angles)
    weights = sum(-scene.links[n].mass * GRAVITY * rates[n][:, 1] for n in scene.links)
    resisting_work = -np.trapezoid(weights - RESISTANCE * np.abs(turns[4]), angles - angles[0])
    assert model.constant == "driving"
    assert np.ptp(model.driving) == 0.0
    # Simpson's rule on either side of the rocker's turning back, where the resistance turns round: 2e-6.
    assert model.driving[0] == pytest.approx(resisting_work / math.radians(45.0), rel=1e-5)
    assert model.energy[-1] == pytest.approx(0.0, abs=1e-9 * resisting_work)


def test_a_swing_given_against_the_lever_s_speed_is_met_from_its_far_end(scene):
    lowered = loads(with_dynamics(FIXTURE).replace("omega   = 4.0", "omega   = -4.0"))
    model = equivalent_model_of(lowered, SAMPLES)
    assert np.degrees(model.driver[[0, -1]]) == pytest.approx([65.0, 20.0], abs=1e-9)
    raised = equivalent_model_of(scene, SAMPLES)
    # The same positions backwards: the same Je at each angle (the two sides of the rocker's turning back, found
    # by bisection where its speed is rest to 1e-9 of the largest, lie a nanoradian apart from either side).
    assert model.inertia == pytest.approx(raised.inertia[::-1], rel=1e-8)


@pytest.mark.parametrize("path,run", [(FIXTURE, "driver.swing"), (SLIDER, "driver.travel")])
@pytest.mark.parametrize("key", ["delta = 0.05", "rpm = 40", "flywheel_shaft_rpm = 1440",
                                 'motor = { kind = "constant", torque = 10 }'])
def test_a_flywheel_or_a_motor_is_refused_for_a_run_made_once(path, run, key):
    with pytest.raises(SceneError) as raised:
        loads(with_dynamics(path, key + "\n"))
    assert raised.value.where == f"dynamics.{key.split()[0]}"
    assert f"run once over {run}" in str(raised.value) and "crank" in str(raised.value)


def test_the_command_line_draws_and_writes_the_swing_s_equivalent_model(tmp_path):
    scene = tmp_path / "swing.toml"
    scene.write_text(with_dynamics(FIXTURE), encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--only", "dynamics,note"]) == 0
    found = json.loads((out / "results.json").read_text(encoding="utf-8"))["dynamics"]
    assert found["equivalent_link"] == "turning" and "flywheel_inertia" not in found
    assert found["angle_deg"][0] == pytest.approx(20.0) and found["angle_deg"][-1] == pytest.approx(65.0)
    drawing = (out / "dynamics.svg").read_text(encoding="utf-8")
    assert "Dynamics: the equivalent model<" in drawing
    # The φ axis is ticked over the swing's 45°, at round steps, not over a turn.
    ticks = {int(t) for t in re.findall(r">(\d+)</text>", drawing)}
    assert {0, 10, 20, 30, 40} <= ticks and not ticks & {50, 60, 90, 360}
    note = (out / "note.md").read_text(encoding="utf-8")
    assert "which rocks over its swing" in note and "over the swing ranges from" in note
    # A swing has no flywheel, and its figure says none (its caption named one); the steps are the scene's
    # count (one sample more than it, 91, was told as the samples: count = 81 over 80° gave 82).
    captions = [line for line in note.splitlines() if line.startswith("Figure") and "Dynamics" in line]
    assert captions and not [line for line in captions if "flywheel" in line]
    # The samples are the steps' ends and the two sides of the rocker's turning back, where its resistance
    # turns round (a corner of Mr, which the works are integrated up to from either side).
    assert f"over the swing ({SAMPLES} steps)" in note and len(found["angle_deg"]) == SAMPLES + 1 + 2
