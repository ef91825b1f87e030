"""The Python interface reviewed as a student or teacher scripts it in a notebook.

The docstrings' examples run as printed; the numbers a motion hands out are checked against closed forms written
here (a four-bar's loop-closure velocities, a slider-crank's position differentiated, a slotted lever's slide), the
balancing moment's sign against the power balance; and a user's mistakes are graphplan's errors, naming what was
asked and what there is. The review found: an unknown point, link, sliding pair or reaction raised a bare
``KeyError`` (printed quoted, no ``GraphplanError``), positions picked past the motion a bare ``IndexError``; a NaN
among 36 000 driver angles was told without its index, a 2-D array without its shape; a frame guide's ``u`` came
out of ``motion.slide(n)`` as one number where the docs promise every slide array ``(N,)``; and the equilibrium's
arrays (``analysis.equilibrium.balancing``) could be written through, where the README says results are read-only.
"""

from __future__ import annotations

import copy
import json
import math
import multiprocessing
import pickle
import textwrap
import tomllib
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

import numpy as np
import pytest

import graphplan
import graphplan.notebook
from graphplan.cli import main

ROOT = Path(__file__).resolve().parents[1]
FIXTURES = ROOT / "fixtures"
RATCHET = FIXTURES / "ratchet_crank_rocker.toml"
HACKSAW = FIXTURES / "offset_slider_crank.toml"
SLOTTED = FIXTURES / "quick_return_slotted_lever.toml"


@pytest.fixture(scope="module")
def ratchet():
    return graphplan.load(RATCHET)


def literal_blocks(doc: str) -> list[str]:
    """The reStructuredText literal blocks (a paragraph ending ``::``, then the indented lines) of a docstring."""
    blocks = []
    parts = doc.split("::\n")
    for part in parts[1:]:
        lines = []
        for line in part.splitlines():
            if line.strip() and not line.startswith(" "):
                break
            lines.append(line)
        blocks.append(textwrap.dedent("\n".join(lines)).strip())
    return [block for block in blocks if block]


def test_every_docstring_example_runs_as_printed(tmp_path, monkeypatch, capsys):
    """The package's and the notebook module's examples, in a student's folder with the fixtures and the
    ``rotor.toml`` that ``graphplan new rotor`` writes, which the notebook's example names."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / "fixtures").symlink_to(FIXTURES)
    assert main(["new", "rotor"]) == 0
    capsys.readouterr()
    owners = [graphplan, graphplan.notebook, *(getattr(graphplan, name) for name in graphplan.__all__),
              *(getattr(graphplan.Scene, verb) for verb in ("solve", "analyse", "plan", "balance", "write"))]
    blocks = [block for owner in owners if isinstance(getattr(owner, "__doc__", None), str)
              for block in literal_blocks(owner.__doc__)]
    assert len(blocks) >= 2
    for block in blocks:
        namespace = {"np": np, "graphplan": graphplan}
        exec(block, namespace)  # noqa: S102 - the docstring's own example, as printed
    assert Path("polygons.png").read_bytes()[:4] == b"\x89PNG"   # the notebook example's rotor.drawing.save


def test_a_crank_rocker_s_rates_are_the_four_bar_s_closed_form(ratchet):
    """ω3, ω4 from A + AB = C + CB differentiated (the loop-closure velocity equations), ε from ω differentiated
    along the crank's turn at constant ω2; clockwise negative, as the docs say (the scene's ω2 = −17 rad/s)."""
    phi = np.radians(np.arange(0.0, 360.0, 0.05))
    motion = graphplan.solve(ratchet, driver=phi)
    crank, coupler, rocker, c = 0.175, 0.55, 0.325, 0.55j
    omega2 = -17.0
    a = crank * np.exp(1j * phi)
    b = motion.point("B").r @ [1, 1j]
    assert np.abs(b - a) == pytest.approx(coupler, abs=1e-12)
    assert np.abs(b - c) == pytest.approx(rocker, abs=1e-12)
    theta3, theta4 = np.angle(b - a), np.angle(b - c)
    # crank·ω2·i·e^{iφ} + AB·ω3·i·e^{iθ3} = CB·ω4·i·e^{iθ4}, solved by Cramer's rule.
    omega3 = crank * omega2 * np.sin(phi - theta4) / (coupler * np.sin(theta4 - theta3))
    omega4 = crank * omega2 * np.sin(phi - theta3) / (rocker * np.sin(theta4 - theta3))
    links = {n: motion.link(n) for n in (2, 3, 4)}
    assert np.allclose(links[2].omega, omega2) and np.allclose(links[2].epsilon, 0.0)
    assert np.allclose(links[3].omega, omega3, rtol=0, atol=1e-12)
    assert np.allclose(links[4].omega, omega4, rtol=0, atol=1e-12)
    assert np.allclose(np.exp(1j * links[3].angle), np.exp(1j * theta3), atol=1e-12)
    assert np.all((links[4].angle > -np.pi) & (links[4].angle <= np.pi))
    step = np.radians(0.05) / omega2   # seconds per sample: dφ/dt = ω2
    for number, omega in ((3, omega3), (4, omega4)):
        by_difference = np.gradient(omega, step)
        assert np.allclose(links[number].epsilon[1:-1], by_difference[1:-1], rtol=0,
                           atol=1e-5 * np.abs(by_difference).max())
    vb = motion.point("B").v @ [1, 1j]
    assert np.allclose(vb, 1j * omega4 * (b - c), rtol=0, atol=1e-12)   # v = ω × CB, m/s


def test_a_slider_crank_s_slider_velocity_is_its_position_differentiated():
    """x_B = r·cos φ + √(l² − (e − r·sin φ)²) along the saw's guide, 80 mm above O; v = ω·dx/dφ, a = dv/dt;
    the slide's own s, velocity and acceleration along its guide alike, each ``(N,)`` as the docs say."""
    scene = graphplan.load(HACKSAW)
    phi = np.radians(np.arange(0.0, 360.0, 0.5))
    motion = graphplan.solve(scene, driver=phi)
    r, rod, e, omega = 0.08, 0.26, 0.08, 6.3
    root = np.sqrt(rod ** 2 - (e - r * np.sin(phi)) ** 2)
    x = r * np.cos(phi) + root
    dx = -r * np.sin(phi) + (e - r * np.sin(phi)) * r * np.cos(phi) / root
    b = motion.point("B")
    assert np.allclose(b.r, np.column_stack([x, np.full_like(x, e)]), rtol=0, atol=1e-12)
    assert np.allclose(b.v[:, 0], omega * dx, rtol=0, atol=1e-12) and np.allclose(b.v[:, 1], 0.0, atol=1e-12)
    by_difference = np.gradient(omega * dx, np.radians(0.5) / omega)
    assert np.allclose(b.a[1:-1, 0], by_difference[1:-1], rtol=0, atol=1e-4 * np.abs(by_difference).max())
    slide = motion.slide(4)
    assert (slide.slider, slide.guide, slide.joint) == (4, 1, "B")
    for name in ("u", "s", "velocity", "acceleration"):
        array = getattr(slide, name)
        assert np.shape(array) == (motion.count,), name   # a frame guide's u was one number, ()
        assert not array.flags.writeable, name
    assert np.allclose(slide.u, 1.0) and np.allclose(slide.s, x, rtol=0, atol=1e-12)
    assert np.allclose(slide.velocity, omega * dx, rtol=0, atol=1e-12)


def test_a_slotted_lever_s_slide_and_coriolis_term_are_the_textbook_s():
    """The block on the crank pin A slides in the lever's slot through C: s = |CA|, ṡ = vA·(CA/|CA|), and
    aA − aA4 = s̈·u + 2·ω4·ṡ·(i·u), the Coriolis term as the slide's docstring writes it."""
    scene = graphplan.load(SLOTTED)
    phi = np.radians(np.arange(0.0, 360.0, 1.0))
    motion = graphplan.solve(scene, driver=phi)
    a = 0.30j + 0.12 * np.exp(1j * phi)
    va, aa = 8.0j * (a - 0.30j), -64.0 * (a - 0.30j)
    along = a / np.abs(a)
    slide = motion.slide(3)
    assert slide.guide == 4
    assert np.allclose(slide.s, np.abs(a), rtol=0, atol=1e-12)
    assert np.allclose(slide.u, along, rtol=0, atol=1e-12)
    assert np.allclose(slide.velocity, np.real(va * np.conj(along)), rtol=0, atol=1e-12)
    assert np.allclose(motion.link(4).omega, np.imag(va * np.conj(a)) / np.abs(a) ** 2, rtol=0, atol=1e-12)
    a4 = motion.point("A4").a @ [1, 1j]
    coriolis = 2j * motion.link(4).omega * slide.velocity * along
    assert np.allclose(aa - a4, slide.acceleration * along + coriolis, rtol=0, atol=1e-12)


def test_an_offset_slot_s_coordinate_counts_from_the_foot_of_the_perpendicular_from_the_pivot():
    """With the slot e off the lever's pivot C, s is what the slide's docstring says: measured along the slot from the
    foot of the perpendicular from C, so A = C + s·u + e·(i·u) and s² + e² = |CA|²."""
    e = 0.02
    text = SLOTTED.read_text(encoding="utf-8").replace("offset = 0.0 ", f"offset = {e} ", 1)
    motion = graphplan.solve(graphplan.load_text(text), driver=np.radians(np.arange(0.0, 360.0, 5.0)))
    a, c = (motion.point(name).r @ [1, 1j] for name in ("A", "C"))
    slide = motion.slide(3)
    assert np.allclose(np.abs(slide.s) ** 2 + e ** 2, np.abs(a - c) ** 2, rtol=0, atol=1e-12)
    foot = a - slide.s * slide.u
    assert np.allclose(np.abs(foot - c), e, rtol=0, atol=1e-12)   # the foot is e from C, on the slot's normal
    assert np.allclose(np.real((foot - c) * np.conj(slide.u)), 0.0, atol=1e-12)


def test_a_plan_s_sliding_values_are_what_the_values_docstring_says_they_are():
    """``VA4A3`` the slide's relative velocity, ``aA4A3^r`` its relative acceleration along the slot, ``aA4A3`` the
    whole of aA4 − aA3 with the Coriolis term in it; the docstring promised "Coriolis terms" among the values,
    which hold none apart."""
    scene = graphplan.load(SLOTTED)
    plans = scene.plan(4)
    doc = type(plans).values.__doc__
    named = {"VA4A3", "aA4A3^r", "aA4A3"}
    assert all(f"``{key}``" in doc for key in named) and named <= set(plans.values)
    motion = graphplan.solve(scene)
    index = 4 - scene.positions.number_from
    slide = motion.slide(3)
    whole = (motion.point("A").a - motion.point("A4").a)[index]
    assert plans.values["VA4A3"] == pytest.approx(abs(slide.velocity[index]), rel=1e-9)
    assert plans.values["aA4A3^r"] == pytest.approx(abs(slide.acceleration[index]), rel=1e-9)
    assert plans.values["aA4A3"] == pytest.approx(math.hypot(*whole), rel=1e-9)
    coriolis = 2 * motion.link(4).omega[index] * slide.velocity[index]
    assert plans.values["aA4A3"] == pytest.approx(math.hypot(slide.acceleration[index], coriolis), rel=1e-9)


def test_the_balancing_moment_is_counter_clockwise_positive_by_the_power_balance():
    """Without masses, the crank's Mb and the rocker's resisting 1500 N·m balance in power: Mb·ω2 = 1500·|ω4|;
    with ω2 = −17 rad/s (clockwise) Mb comes out negative, clockwise, as "ccw positive" says it should."""
    tables = tomllib.loads(RATCHET.read_text(encoding="utf-8"))
    for massive in ("links", "measured", "points"):
        del tables[massive]
    del tables["loads"][0]["during"]
    tables["positions"]["plans"] = []
    analysis = graphplan.load(tables).analyse()
    omega4 = analysis.motion.link(4).omega
    balancing = analysis.equilibrium.balancing
    assert np.allclose(balancing, 1500.0 * np.abs(omega4) / -17.0, rtol=1e-9, atol=1e-9)
    assert balancing[np.abs(omega4) > 0.1].max() < 0


def test_the_equilibrium_s_arrays_cannot_be_written_through(ratchet):
    """``analysis.equilibrium.balancing[:] = 0`` went through, and the analysis's drawings and tables then read
    the zeros; the README's arrays are read-only."""
    equilibrium = ratchet.analyse().equilibrium
    with pytest.raises(ValueError, match="read-only"):
        equilibrium.balancing[0] = 0.0
    with pytest.raises(ValueError, match="read-only"):
        equilibrium.reaction("R23").force[0] = 0.0
    for array in (equilibrium.condition, equilibrium.singular, equilibrium.locked):
        assert not array.flags.writeable


def test_a_name_or_number_the_motion_has_not_is_graphplan_s_error_naming_what_there_is(ratchet):
    """They were bare KeyErrors, printed quoted ("'no link 9; …'") and missed by ``except GraphplanError``, as
    the README says bad input raises; still KeyErrors (and IndexError) for code that catches those."""
    motion = graphplan.solve(ratchet, driver=np.radians([10.0, 20.0, 30.0]))
    for ask, told in ((lambda: motion.point("Z"), "no point 'Z'; points are O, C, A, S2, B, S3, E, S4"),
                      (lambda: motion.link(9), "no link 9; links are 1, 2, 3, 4"),
                      (lambda: motion.slide(4), "link 4 slides in no pair; the mechanism has no sliding pair")):
        with pytest.raises(graphplan.GraphplanError) as raised:
            ask()
        assert isinstance(raised.value, KeyError) and isinstance(raised.value, graphplan.UnknownNameError)
        assert str(raised.value) == told
    with pytest.raises(graphplan.UnknownNameError, match=r"^no reaction 'R99'; reactions are R12, R23, R34, R14$"):
        ratchet.analyse().equilibrium.reaction("R99")
    with pytest.raises(graphplan.PositionIndexError, match=r"^the motion has 3 positions, indices 0 to 2") as raised:
        motion.at_positions([0, 3])
    assert isinstance(raised.value, IndexError) and isinstance(raised.value, graphplan.GraphplanError)


def test_a_nan_among_a_dense_sweep_is_told_by_its_index_and_how_many_more(ratchet):
    angles = np.radians(np.arange(0.0, 360.0, 0.01))
    angles[[20_000, 30_000, 30_001]] = np.nan
    with pytest.raises(graphplan.SceneError) as raised:
        graphplan.solve(ratchet, driver=angles)
    assert str(raised.value) == ("driver[20000]: must be a finite number, a driver position (got nan); "
                                 "2 more after it are not finite either")


def test_a_grid_of_angles_is_told_by_its_shape(ratchet):
    grid, _ = np.meshgrid(np.radians([0.0, 90.0, 180.0]), [1.0, 2.0])
    with pytest.raises(graphplan.SceneError, match=r"^driver: must be a non-empty 1-D array of driver positions "
                                                   r"\(got an array of shape \(2, 3\)\): give np\.ravel\(driver\)"):
        graphplan.solve(ratchet, driver=grid)


def test_one_angle_is_one_position_as_solve_s_docstring_says(ratchet):
    motion = graphplan.solve(ratchet, driver=0.3)
    assert motion.point("B").r.shape == (1, 2) and motion.link(4).omega.shape == (1,)
    assert motion.point("B").r[0] == pytest.approx(graphplan.solve(ratchet, driver=[0.0, 0.3]).point("B").r[1])


def _largest_slider_acceleration(rod: float) -> float:
    """A worker's share of a parameter sweep: the scene's tables changed, then checked by load, as the README's
    sweep does."""
    tables = tomllib.loads((FIXTURES / "engine_slider_crank.toml").read_text(encoding="utf-8"))
    tables["groups"][0]["length"] = rod
    return float(np.abs(graphplan.load(tables).solve(np.radians(np.arange(0.0, 360.0, 1.0))).point("B").a).max())


def test_a_parameter_sweep_runs_in_a_process_pool_and_scenes_travel_to_it(ratchet):
    """README: scenes and motions pickle (to a process pool's workers); the pool's answers are the ones the
    notebook's own process gives, and a scene sent there and back solves as it did."""
    rods = [0.2, 0.3, 0.4]
    # Spawned, as Windows' and macOS's pools start their workers: forked from a pytest worker that has threads
    # running, a child may deadlock on a lock one of them held (Python 3.12 and later warn of it, as 3.13 did here).
    with ProcessPoolExecutor(max_workers=2, mp_context=multiprocessing.get_context("spawn")) as pool:
        swept = list(pool.map(_largest_slider_acceleration, rods))
        travelled = pool.submit(copy.copy, ratchet).result()
    assert swept == [_largest_slider_acceleration(rod) for rod in rods]
    # a shorter rod swings the slider harder: ω²·r·(1 + r/l) at the dead centre grows as l shrinks
    assert swept[0] > swept[1] > swept[2]
    assert travelled == ratchet
    motion = graphplan.solve(travelled, driver=[0.1, 0.2])
    again = pickle.loads(pickle.dumps(motion))
    assert np.array_equal(again.link(3).epsilon, graphplan.solve(ratchet, driver=[0.1, 0.2]).link(3).epsilon)
    assert math.isclose(float(again.driver[1]), 0.2)


def test_the_first_value_is_named_by_its_index_as_the_others_are():
    """The branches are taken at the first value: a value there the mechanism cannot reach, or a toggle, was told
    as «φ = 360°» alone where the same value second was «φ = 360° (driver[1])»."""
    swing = graphplan.load(FIXTURES / "double_rocker_swing.toml")
    with pytest.raises(graphplan.AssemblyError, match=r"^B cannot be assembled at φ = 360° \(driver\[0\]\) in "
                                                      r"group II\(3,4\): .*link 2 reaches only from 13\.10°"):
        graphplan.solve(swing, driver=[-1e-9, 0.5])
    # A parallelogram four-bar: at φ = 180° the coupler and rocker lie along the frame, a toggle.
    tables = tomllib.loads(RATCHET.read_text(encoding="utf-8"))
    tables["frame"]["points"]["C"] = [1.0, 0.0]
    tables["driver"]["length"], tables["groups"][0]["lengths"] = 0.5, [1.0, 0.5]
    for key in ("points", "links", "loads", "measured", "drawing"):
        tables.pop(key)
    tables["positions"] = {"count": 12}
    parallelogram = graphplan.load(tables)
    with pytest.raises(graphplan.SingularPositionError, match=r"^singular position at φ = 180° \(driver\[0\]\) "):
        graphplan.solve(parallelogram, driver=[math.pi, 0.5])


def test_the_equivalent_model_s_arrays_cannot_be_written_through():
    """``je = model.inertia; je -= je.mean()`` (a student plotting Je's fluctuation) went through into the model,
    and the flywheel worked out from it after was another."""
    dynamics = graphplan.load(Path(__file__).parent / "scenes" / "compressor_indicator_diagram.toml").machine_dynamics()
    model = dynamics.model
    with pytest.raises(ValueError, match="read-only"):
        je = model.inertia
        je -= je.mean()
    for array in (model.driver, model.coordinate, model.inertia_slope, model.driving, model.resisting,
                  model.driving_work, model.resisting_work, *model.link_inertia.values()):
        assert not array.flags.writeable
    assert dynamics.flywheel.inertia > 0
    with pytest.raises(ValueError, match="read-only"):
        dynamics.flywheel.omega[0] = 0.0


def test_the_machine_s_motion_cannot_be_written_through(tmp_path, capsys):
    """``w = dynamics.motion.omega; w *= 30 / np.pi`` (ω in rpm for a plot) went through into the motion, whose
    results, note and motion.svg then read rpm as rad/s."""
    assert main(["new", "shaper", "--out", str(tmp_path / "shaper.toml")]) == 0
    capsys.readouterr()
    motion = graphplan.load(tmp_path / "shaper.toml").machine_dynamics().motion
    with pytest.raises(ValueError, match="read-only"):
        w = motion.omega
        w *= 30 / np.pi
    assert not (motion.t.flags.writeable or motion.phi.flags.writeable or motion.motor_torque.flags.writeable)


def test_a_rotor_s_and_a_machine_s_results_changed_by_a_script_are_the_run_s_again_when_asked_again(tmp_path):
    """rotor.results and shaking.results were one cached dict each: a script that zeroed a correction in what it
    was handed (to tabulate, to plot) was handed the zero on every later ask."""
    from graphplan.starters import starter

    scene_file = tmp_path / "rotor.toml"
    scene_file.write_text(starter("rotor", "en"), encoding="utf-8")
    assert main(["run", str(scene_file), "--out", str(tmp_path / "out"), "--only", "balancing,vibration"]) == 0
    written = json.loads((tmp_path / "out" / "results.json").read_text(encoding="utf-8"))
    scene = graphplan.load(scene_file)
    rotor, shaking = scene.balance(), scene.vibration_response()
    rotor.results["planes"][0]["mass_radius"] = 0.0
    shaking.results["amplitude"] = -1.0
    assert rotor.results["planes"] == written["balancing"]["planes"]
    assert shaking.results["amplitude"] == written["vibration"]["amplitude"]
