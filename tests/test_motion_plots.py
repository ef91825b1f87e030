"""The figure of the machine's motion: what it draws is the integrated motion and its events, in the scene's language."""

from __future__ import annotations

import json
import math
import re

import numpy as np
import pytest
from test_dynamics_without_linkage import PRESS

from graphplan.cli import main
from graphplan.locale import strings
from graphplan.machine_motion import Brake, Clutch, ConstantTorque, LinearMotor, Machine, Stall, Start, simulate
from graphplan.report.motion_plots import motion_plot

pytest.importorskip("matplotlib")

# A machine whose load swings over the turn (M + A·sin φ), run up through a clutch by a linear motor,
# switched off and braked to rest: every part of the figure has something to draw.
LOAD, SWING, INERTIA = 40.0, 25.0, 2.0


def run_down_motion():
    machine = Machine(INERTIA, resisting=lambda phi, omega: LOAD + SWING * math.sin(phi))
    motor = LinearMotor(200.0, 30.0, rotor_inertia=0.2)
    return simulate(machine, motor, clutch=Clutch(150.0, engage_at=0.2), motor_off_at=12.0,
                    brake=Brake(torque=60.0, at=12.5), rtol=1e-8)


@pytest.fixture(scope="module")
def motion():
    return run_down_motion()


def legend_texts(axes) -> list[str]:
    return [item.get_text() for item in axes.get_legend().get_texts()]


def test_the_run_shows_each_event_numbered_in_time_and_the_band_of_the_steady_state(motion):
    from matplotlib import pyplot

    text = strings("ru")
    figure = motion_plot(motion, text, "Пресс v1.2")
    run, _ = figure.axes
    try:
        names = [name for _, name in motion.events]
        assert names == ["clutch engaged", "clutch locked", "motor off", "brake on", "stopped"]
        legend = legend_texts(run)
        for number, (when, name) in enumerate(motion.events, start=1):
            words = text[f"motion_event_{name.replace(' ', '_')}"]
            assert f"{number}: {words}, t = {f'{when:.4g}'.replace('.', ',')} с" in legend
        # The band of the steady state starts where it was reached and ends where the motor is switched off.
        band = next(item for item in run.collections if item.get_label().startswith("установившийся"))
        corners = band.get_paths()[0].vertices
        assert corners[:, 0].min() == pytest.approx(motion.steady.reached_at)
        assert corners[:, 0].max() == pytest.approx(motion.event_time("motor off"))
        assert corners[:, 1].min() == pytest.approx(motion.steady.cycle.min_speed)
        assert corners[:, 1].max() == pytest.approx(motion.steady.cycle.max_speed)
        # The run is drawn to its end at rest, not beyond.
        assert run.get_xlim()[1] == pytest.approx(motion.stopped_at)
        assert figure._suptitle.get_text().endswith("Пресс v1.2")   # the user's title keeps its point
    finally:
        pyplot.close(figure)


def test_the_steady_turn_is_one_whole_turn_between_the_steady_extremes(motion):
    from matplotlib import pyplot

    figure = motion_plot(motion, strings("en"))
    _, turn = figure.axes
    try:
        integrated = turn.get_lines()[0]
        angles, speeds = integrated.get_xdata(), integrated.get_ydata()
        assert angles[0] == pytest.approx(0.0, abs=1e-6) and angles[-1] == pytest.approx(360.0, abs=1e-6)
        assert np.all(np.diff(angles) > 0)
        cycle = motion.steady.cycle
        assert speeds.max() == pytest.approx(cycle.max_speed, rel=1e-6)
        assert speeds.min() == pytest.approx(cycle.min_speed, rel=1e-6)
        # With the load M + A·sin φ the shaft is slowest just after the load's peak at 90°, fastest after its trough.
        assert 90.0 < angles[np.argmin(speeds)] < 180.0 and 270.0 < angles[np.argmax(speeds)] <= 360.0
    finally:
        pyplot.close(figure)


@pytest.mark.parametrize("switched_off", [False, True])
def test_the_steady_turns_title_says_it_is_the_last_whole_steady_turn_and_gives_its_start(motion, switched_off):
    """The note says the machine runs steadily from t = 1.655 s; the plot's turn, titled "the steady turn (from
    t = 4.57 s)", read as a second, later start of the steady state.  It is the last whole turn before the steady
    run ends (the run's end, or the motor switched off): no whole turn more fits after it."""
    from matplotlib import pyplot

    if not switched_off:
        machine = Machine(INERTIA, resisting=lambda phi, omega: LOAD + SWING * math.sin(phi))
        motion = simulate(machine, LinearMotor(200.0, 30.0, rotor_inertia=0.2), rtol=1e-8)
    steady_end = motion.event_time("motor off") if switched_off else float(motion.t[-1])
    text = strings("en")
    figure = motion_plot(motion, text)
    _, turn = figure.axes
    try:
        title = turn.get_title()
        assert title.startswith(text["motion_turn"].split("{")[0]) and "last whole steady turn" in title
        start = float(re.search(r"t = ([\d.]+) s", title).group(1))
        # A whole turn by the integrated angle itself, not by the program's cycle: φ advances 2π from the start.
        phi = lambda time: float(np.interp(time, motion.t, motion.phi))
        end = float(motion.t[np.searchsorted(motion.phi, phi(start) + 2 * math.pi)])
        period = end - start
        assert start >= motion.steady.reached_at - 1e-3
        assert end <= steady_end + 1e-3 < end + period
    finally:
        pyplot.close(figure)


@pytest.mark.parametrize("start_deg", [180.0, 97.0])
def test_the_steady_turn_of_a_run_started_away_from_position_1_spans_the_whole_turn(start_deg):
    """A run that starts at 180° from position 1 has its steady turn from 180° to 540°: drawn over 0…360°, the
    part past 360° from 0°, not left outside the axis (the turn's lower half, with ωmin, was missing)."""
    from matplotlib import pyplot

    machine = Machine(INERTIA, resisting=lambda phi, omega: LOAD + SWING * math.sin(phi))
    motion = simulate(machine, LinearMotor(200.0, 30.0, rotor_inertia=0.2),
                      start=Start(angle=math.radians(start_deg)), rtol=1e-8)
    figure = motion_plot(motion, strings("en"))
    _, turn = figure.axes
    try:
        integrated = turn.get_lines()[0]
        angles, speeds = np.asarray(integrated.get_xdata(), float), np.asarray(integrated.get_ydata(), float)
        drawn = np.isfinite(angles)
        assert np.all((angles[drawn] >= 0.0) & (angles[drawn] <= 360.0))
        assert angles[drawn].min() == pytest.approx(0.0, abs=1e-9)
        assert angles[drawn].max() == pytest.approx(360.0, abs=1e-9)
        # Every degree of the turn is drawn, with no gap wider than the samples' spacing.
        covered = np.sort(angles[drawn])
        assert np.max(np.diff(covered)) < 2.0
        cycle = motion.steady.cycle
        assert np.nanmax(speeds) == pytest.approx(cycle.max_speed, rel=1e-6)
        assert np.nanmin(speeds) == pytest.approx(cycle.min_speed, rel=1e-6)
        # The same turn as the one a run from position 1 settles in, angle for angle.
        assert 90.0 < angles[np.nanargmin(speeds)] < 180.0 and 270.0 < angles[np.nanargmax(speeds)] <= 360.0
    finally:
        pyplot.close(figure)


def test_a_scene_with_a_motor_gets_the_figure_of_its_motion_and_one_without_none(tmp_path):
    scene = tmp_path / "press.toml"
    scene.write_text(PRESS, encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "still")]) == 0
    assert not (tmp_path / "still" / "motion.svg").exists()
    scene.write_text(PRESS + 'motor = { kind = "linear", stall_torque = 2000, no_load_rpm = 110 }\n', encoding="utf-8")
    out = tmp_path / "driven"
    assert main(["run", str(scene), "--out", str(out)]) == 0
    svg = (out / "motion.svg").read_text(encoding="utf-8")
    assert svg.startswith("<?xml") and "<path" in svg
    # The figure is drawn from the same integration as the results: one run, the same numbers.
    motion = json.loads((out / "results.json").read_text(encoding="utf-8"))["dynamics"]["motion"]
    assert motion["delta"] > 0 and motion["start_up_time"] < motion["steady_after"]
    # The same scene draws the same bytes.
    assert main(["run", str(scene), "--out", str(tmp_path / "again")]) == 0
    assert (tmp_path / "again" / "motion.svg").read_text(encoding="utf-8") == svg


def test_a_stalled_run_shows_the_motors_torque_falling_short_of_the_resistance_where_it_stalls():
    """A load light for the first quarter turn and heavy after it, a motor (through a 3:1 gear) whose torque
    at rest is between the two: the shaft runs up, passes 90° on what it has gained, and stalls there. The
    lower plot sets the motor's torque along the run against Mr(φ); at the stall the motor gives its
    torque at rest, M0·i, and Mr is above it."""
    count = 360
    angles = 2.0 * np.pi * np.arange(count) / count
    light, heavy, stall_torque, gear = 10.0, 100.0, 10.0, 3.0
    resisting = np.where(angles < np.pi / 2, light, heavy)
    motion = simulate(Machine(INERTIA, resisting=resisting), LinearMotor(stall_torque, 100.0, gear_ratio=gear),
                      rtol=1e-8)
    assert motion.stalled_at is not None and 90.0 < motion.stalled_at_angle_deg < 180.0
    text = strings("ru")
    figure = motion_plot(motion, text, "Пресс", resisting=(angles, resisting))
    lower = figure.axes[1]
    lines = {line.get_label(): line for line in lower.get_lines()}
    mr, md = lines[text["motion_resisting"].format()], lines[text["motion_motor_torque"].format()]
    (point,) = [line for label, line in lines.items() if label.startswith("остановка при t")]
    x, y = (float(value[0]) for value in point.get_data())
    assert x == pytest.approx(math.degrees(motion.phi[-1]))
    assert y == pytest.approx(stall_torque * gear, rel=1e-3)
    assert float(np.interp(x, *mr.get_data())) == pytest.approx(heavy) and heavy > y
    # Mr as given, over the whole turn the stall is in.
    along, drawn = mr.get_data()
    assert along[0] == 0.0 and along[-1] == 360.0
    assert drawn == pytest.approx(np.interp(np.radians(along), angles, resisting, period=2 * np.pi))
    assert md.get_data()[0][-1] == pytest.approx(x)


def test_a_machine_that_never_moves_gets_only_the_plot_of_why():
    """A motor whose torque at rest (through its gear) is below the resistance everywhere: the speed over time
    would be an empty plot along its axis, so the figure is the moments alone, the stall at φ = 0."""
    count = 360
    angles = 2.0 * np.pi * np.arange(count) / count
    resisting = np.full(count, 100.0)
    motion = simulate(Machine(INERTIA, resisting=resisting), LinearMotor(10.0, 100.0, gear_ratio=3.0))
    assert motion.stalled_at == 0.0 and not np.any(motion.omega)
    text = strings("en")
    figure = motion_plot(motion, text, resisting=(angles, resisting))
    (only,) = figure.axes
    labels = {line.get_label() for line in only.get_lines()}
    # The motor held at rest, at its starting torque across the turn (drawn along a run of no length, it was no line).
    assert {text["motion_resisting"].format(), text["motion_motor_torque_at_rest"].format()} <= labels
    assert text["motion_shaft"] not in labels


def test_a_machine_that_moves_keeps_its_speed_over_time(motion):
    figure = motion_plot(motion, strings("en"))
    assert len(figure.axes) == 2


def test_a_run_down_with_no_steady_state_is_the_speed_in_time_alone_with_no_empty_half():
    """Motor off from the start, braked to rest: there is no steady turn to draw, and the lower half of the
    figure was empty but for "no steady state within the run"."""
    machine = Machine(INERTIA, resisting=lambda phi, omega: LOAD)
    motion = simulate(machine, LinearMotor(200.0, 30.0), start=Start(omega=20.0), motor_off_at=0.0,
                      brake=Brake(torque=60.0, at=0.0))
    assert motion.steady is None and motion.stopped_at == pytest.approx(INERTIA * 20.0 / (LOAD + 60.0), rel=1e-6)
    text = strings("en")
    figure = motion_plot(motion, text)
    (only,) = figure.axes
    assert text["motion_shaft"] in {line.get_label() for line in only.get_lines()}
    assert text["motion_no_steady"] not in {item.get_text() for item in figure.findobj(lambda a: hasattr(a, "get_text"))}


def test_a_stall_from_a_start_off_position_1_is_drawn_over_the_angle_turned_from_that_start():
    """Started at φ = 200° of the run, the machine stalls 90° on: the axis says "φ turned from the start", so the
    dot is at the angle turned, Mr is drawn as it is at the start plus that angle, and the legend gives both.  The
    dot was at the run's own φ, past the turn the axis drew (450° for 90° turned)."""
    count = 360
    angles = 2.0 * np.pi * np.arange(count) / count
    start = math.radians(200.0)
    # Light for the quarter turn after the start, heavy after it: the shaft passes it on what it gained.
    resisting = np.where((angles - start) % (2 * np.pi) < np.pi / 2, 10.0, 100.0)
    motion = simulate(Machine(INERTIA, resisting=resisting), LinearMotor(10.0, 100.0, gear_ratio=3.0),
                      start=Start(angle=start), rtol=1e-8)
    turned = math.degrees(motion.phi[-1] - start)
    assert motion.stalled_at is not None and 90.0 < turned < 180.0
    text = strings("en")
    figure = motion_plot(motion, text, resisting=(angles, resisting), stall_angle_deg=123.4)
    lower = figure.axes[1]
    lines = {line.get_label(): line for line in lower.get_lines()}
    (point,) = [line for label, line in lines.items() if label.startswith("stalls at t")]
    assert float(point.get_xdata()[0]) == pytest.approx(turned)
    assert f"{turned:.4g}° from the start (φ = 123.4°)" in point.get_label()
    along, drawn = lines[text["motion_resisting"].format()].get_data()
    assert along[0] == 0.0 and along[-1] == 360.0
    assert float(np.interp(45.0, along, drawn)) == pytest.approx(10.0)
    assert float(np.interp(turned, along, drawn)) == pytest.approx(100.0)


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_a_stall_through_a_slipping_clutch_is_blamed_on_the_clutch_in_a_title_that_stays_on_the_figure(locale):
    """A 30 N·m clutch slipping from the start against Mr = 20 + 35·sin φ: the machine stalls with the clutch still
    slipping.  Drawn without the moments (the library call with no Mr), the title blamed the motor and ran off both
    sides of the figure in one line."""
    from matplotlib import pyplot

    angles = 2.0 * np.pi * np.arange(720) / 720
    motion = simulate(Machine(INERTIA, resisting=20.0 + 35.0 * np.sin(angles)), LinearMotor(300.0, 100.0,
                      rotor_inertia=1.0), clutch=Clutch(30.0), start=Start(driving_omega=90.0), rtol=1e-8)
    assert motion.stalled_at is not None and motion.stalled_slipping
    text = strings(locale)
    figure = motion_plot(motion, text)
    (run,) = figure.axes
    try:
        title = run.title
        def tail(key):  # the words after the numbers, which blame the clutch or the motor
            return re.sub(r"\s", "", text[key].rsplit("}", 1)[1])

        said = re.sub(r"\s", "", title.get_text())
        assert tail("motion_stalled_clutch") in said and tail("motion_stalled") not in said
        assert "\n" in title.get_text()
        figure.canvas.draw()
        extent, page = title.get_window_extent(), figure.bbox
        assert page.x0 <= extent.x0 and extent.x1 <= page.x1
    finally:
        pyplot.close(figure)


def held_by_clutch(tmp_path, capsys, clutch: float, brake: str = "") -> tuple[str, str]:
    """A 150 N·m motor behind a clutch of ``clutch`` N·m against a constant 50 N·m, run from the command line: its
    warning line and its note."""
    scene = tmp_path / "held.toml"
    scene.write_text('[scene]\ntitle = "held by its clutch"\n[dynamics]\ninertia = 2.0\nrpm = 90\n'
                     "resisting_torque = [[0, 50], [360, 50]]\n"
                     'motor = { kind = "constant", torque = 150, rotor_inertia = 1.0 }\n'
                     f"clutch = {{ torque = {clutch} }}\nduration = 2.0\n{brake}", encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "out")]) == 0
    told = next(line for line in capsys.readouterr().out.splitlines() if line.startswith("warning:"))
    return told, (tmp_path / "out" / "note.md").read_text(encoding="utf-8")


@pytest.mark.parametrize("brake", ["", "brake = { torque = 40 }\n"])
def test_a_clutch_slipping_with_the_shaft_never_turned_is_told_the_machine_does_not_start_for_the_clutch(
        tmp_path, capsys, brake):
    """A 150 N·m motor behind a 30 N·m clutch against a constant 50 N·m: the clutch slips from the start and the
    shaft never turns, with or without a 40 N·m brake on from the start (30 N·m would not turn it against the 50
    alone).  The warning and the note said the motor's 150 N·m did not overcome 50 N·m; then that the machine
    stalled, coming to rest at t = 0, where it never moved."""
    clutch, resisting = 30.0, 50.0
    told, note = held_by_clutch(tmp_path, capsys, clutch, brake)
    assert told == (f"warning: dynamics: the machine does not start: at rest at φ = 0° the clutch, slipping at its "
                    f"{clutch:g} N·m, does not overcome the resistance there, {resisting:g} N·m (a clutch of more "
                    "torque)")
    text = strings("en")
    assert text["note_dyn_never_starts_clutch"].format(angle="0°", torque=f"{clutch:g}",
                                                       resisting=f"{resisting:g}") in note
    assert "stalls" not in note and "brake applied" not in note


def test_a_shaft_held_at_rest_behind_its_slipping_clutch_shows_every_line_its_legend_names():
    """A constant 150 N·m motor behind a 20 N·m clutch against a constant 50 N·m: the shaft never turns while the
    driving half spins up.  The shaft's ω = 0 ran along the axes' frame, which hid it, and the moments named the
    motor's torque "along the run", a line of no length at 0°: two legend entries for nothing seen."""
    from matplotlib import pyplot
    from matplotlib.lines import Line2D

    resisting = np.full(360, 50.0)
    angles = 2.0 * np.pi * np.arange(360) / 360
    motion = simulate(Machine(2.0, resisting=resisting), ConstantTorque(150.0, rotor_inertia=1.0), clutch=Clutch(20.0),
                      duration=0.5)
    assert motion.stalled_slipping and not motion.turned and np.all(motion.omega == 0.0)
    figure = motion_plot(motion, strings("en"), resisting=(angles, resisting))
    try:
        run, turn = figure.axes
        for plot in (run, turn):
            frame = max(spine.get_zorder() for spine in plot.spines.values())
            for line in plot.get_lines():
                xs, ys = (np.asarray(values, dtype=float) for values in line.get_data())
                if line.get_label().startswith("_") or not xs.size:  # unnamed, or an event's words in the legend
                    continue
                # A line runs some way across its plot; a marker is a point.
                assert line.get_marker() not in ("None", "", None) or np.ptp(xs) > 0, line.get_label()
                on_frame = np.all(ys == plot.get_ylim()[0]) or np.all(ys == plot.get_ylim()[1])
                assert not on_frame or (line.get_zorder() > frame and not line.get_clip_on()), line.get_label()
        shaft = next(line for line in run.get_lines() if line.get_label() == strings("en")["motion_shaft"])
        assert isinstance(shaft, Line2D) and np.all(shaft.get_ydata() == 0.0)
    finally:
        pyplot.close(figure)


def test_a_clutch_that_would_start_the_machine_but_for_the_brake_on_from_the_start_blames_the_brake(tmp_path, capsys):
    """A 60 N·m clutch against 50 N·m would start the machine; a 40 N·m brake on from the start makes 90 N·m,
    and holds it.  The warning and the note said the clutch's 60 N·m could not pass 50 N·m and advised a larger
    clutch."""
    told, note = held_by_clutch(tmp_path, capsys, 60.0, "brake = { torque = 40 }\n")
    assert told == ("warning: dynamics: the machine does not start: at rest at φ = 0° the driving torque, 60 N·m, "
                    "does not overcome the resistance there and the brake applied at t = 0 s, 50 + 40 = 90 N·m: the "
                    "brake's torque (dynamics.brake.torque) holds the machine from the start (a later "
                    "dynamics.brake.at, after the start-up, or a smaller brake torque)")
    text = strings("en")
    assert text["note_dyn_never_starts_braked"].format(angle="0°", torque="60", resisting="50", brake="40", at="0",
                                                       total="90") in note
    assert "clutch of a larger torque" not in note


# A machine of 2 kg·m² driven by a constant 150 N·m against 100 N·m up to 200°, 145 falling to 110 N·m from there to
# 300°, 100 N·m after: it runs up at (150 − 100)/2 = 25 rad/s² and is still short of 200° at 0.5 s, where a brake of
# 80 N·m comes on; 150 N·m cannot turn it against 100 + 80 or more anywhere, and it stalls.
BRAKED_TABLE = [(0.0, 100.0), (200.0, 100.0), (200.0, 145.0), (300.0, 110.0), (300.0, 100.0), (360.0, 100.0)]
BRAKE_TORQUE, BRAKE_AT, MOTOR_TORQUE, BRAKED_INERTIA = 80.0, 0.5, 150.0, 2.0


def braked_dynamics(brake: str, motor_torque: float = MOTOR_TORQUE):
    import tomllib

    from graphplan.machine_dynamics import MachineDynamics
    from graphplan.scene import load

    table = ", ".join(f"[{angle:g}, {moment:g}]" for angle, moment in BRAKED_TABLE)
    return MachineDynamics(load(tomllib.loads(
        f'[scene]\ntitle = "braked"\n[dynamics]\ninertia = {BRAKED_INERTIA}\nrpm = 90\nresisting_torque = [{table}]\n'
        f'motor = {{ kind = "constant", torque = {motor_torque} }}\nduration = 3.0\n{brake}')))


def scene_mr(turned_deg: np.ndarray) -> np.ndarray:
    """Mr as the scene's table gives it, piece by piece between its jumps (the run starts at 0°)."""
    angles, moments = np.array(BRAKED_TABLE).T
    within = np.asarray(turned_deg) % 360.0
    falling = np.interp(within, angles[2:4], moments[2:4])
    return np.where(within < 200.0, 100.0, np.where(within < 300.0, falling, 100.0))


def brake_line(axes, text):
    """The lower plot's line of Mr + Mt, found by its label's words before the numbers; None where there is none."""
    # Cut at the first number filled in: the words before it are mathtext, whose own braces the locale doubles.
    words = text["motion_resisting_braked"].format(torque="\0", at="\0").split("\0")[0]
    found = [line for line in axes.get_lines() if line.get_label().startswith(words)]
    assert len(found) <= 1
    return found[0] if found else None


@pytest.mark.parametrize(("locale", "brake_word"), [("en", "brake"), ("ru", "тормоз"), ("zh", "制动器")])
def test_a_brake_that_brings_the_machine_to_rest_is_drawn_on_top_of_mr_from_where_it_came_on(locale, brake_word):
    """The lower plot drew the motor's 150 N·m above Mr's 100 N·m, which read as a machine that should not stall.
    From where the brake came on, the shaft having turned ½·25·0.5² = 3.125 rad = 179.05° at constant acceleration,
    the resistance the motor falls short of is Mr(φ) + 80 N·m: a step up from Mr there, and Mr + 80 on after it."""
    from matplotlib import pyplot

    dynamics = braked_dynamics(f"brake = {{ torque = {BRAKE_TORQUE}, at = {BRAKE_AT} }}\n")
    motion = dynamics.motion
    text = strings(locale)
    figure = motion_plot(motion, text, "braked", resisting=dynamics.resisting,
                         stall_angle_deg=dynamics.rest_angle_deg())
    try:
        lower = figure.axes[1]
        line = brake_line(lower, text)
        mark = text["decimal_mark"]
        assert line.get_label() == text["motion_resisting_braked"].format(torque="80", at=f"0{mark}5")
        assert brake_word in line.get_label() and line.get_label() in legend_texts(lower)
        along, drawn = (np.asarray(values, dtype=float) for values in line.get_data())
        acceleration = (MOTOR_TORQUE - 100.0) / BRAKED_INERTIA
        on = math.degrees(0.5 * acceleration * BRAKE_AT ** 2)
        assert on < 200.0  # still where Mr is 100 N·m
        # Before the brake's angle nothing but Mr; at it, the step from Mr up to Mr + Mt.
        assert along.min() == pytest.approx(on, abs=1e-6) and along[0] == along[1]
        assert drawn[0] == pytest.approx(100.0) and drawn[1] == pytest.approx(100.0 + BRAKE_TORQUE)
        # After it, Mr(φ) + Mt over the rest of the plot, the jumps themselves left out (drawn at either side).
        after = along[1:]
        clear = np.all(np.abs(after[:, None] % 360.0 - np.array([200.0, 300.0])) > 1e-6, axis=1)
        assert drawn[1:][clear] == pytest.approx(scene_mr(after[clear]) + BRAKE_TORQUE)
        assert after[-1] == 720.0 and np.any((after % 360.0 > 200.0) & (after % 360.0 < 300.0))
        # Mr is still drawn alone over the whole plot, and the motor's torque falls short of the brake's line only.
        mr_along, mr = (np.asarray(values, dtype=float) for values in lower.get_lines()[0].get_data())
        assert lower.get_lines()[0].get_label() == text["motion_resisting"].format() and mr_along[0] == 0.0
        clear = np.all(np.abs(mr_along[:, None] % 360.0 - np.array([200.0, 300.0])) > 1e-6, axis=1)
        assert mr[clear] == pytest.approx(scene_mr(mr_along[clear]))
        assert np.all(motion.motor_torque > scene_mr(np.degrees(motion.phi)))
        assert MOTOR_TORQUE < float(np.min(drawn[1:]))
        assert re.sub(r"\s", "", lower.get_title()) == re.sub(r"\s", "", text["motion_stall_title"])
    finally:
        pyplot.close(figure)


def test_a_brake_on_from_the_start_that_holds_the_machine_makes_the_whole_curve_mr_and_the_brake():
    """Applied at t = 0, the brake holds the machine where it stands (150 N·m against 100 + 80): the resistance is
    Mr + Mt from the start, no step in it."""
    from matplotlib import pyplot

    dynamics = braked_dynamics(f"brake = {{ torque = {BRAKE_TORQUE} }}\n")
    assert not dynamics.motion.turned
    text = strings("en")
    figure = motion_plot(dynamics.motion, text, "braked", resisting=dynamics.resisting,
                         stall_angle_deg=dynamics.rest_angle_deg())
    try:
        (only,) = figure.axes
        along, drawn = (np.asarray(values, dtype=float) for values in brake_line(only, text).get_data())
        assert along[0] == 0.0 and along[-1] == 360.0 and np.all(np.diff(along) > 0)
        clear = np.all(np.abs(along[:, None] - np.array([200.0, 300.0])) > 1e-6, axis=1)
        assert drawn[clear] == pytest.approx(scene_mr(along[clear]) + BRAKE_TORQUE)
    finally:
        pyplot.close(figure)


@pytest.mark.parametrize("brake", ["", "brake = { damping = 1.0 }\n", f"brake = {{ torque = {BRAKE_TORQUE} }}\n"])
def test_a_machine_no_brake_holds_draws_no_brake_curve(brake):
    """A motor of 90 N·m against 100 N·m does not start, with no brake, one of damping alone, which takes nothing
    at rest, or one of 80 N·m on from the start, which the motor would not start against Mr alone either (that
    brake was blamed, and the advice was to apply it later): the motor is what falls short, and the plot sets it
    against Mr alone."""
    from matplotlib import pyplot

    dynamics = braked_dynamics(brake, motor_torque=90.0)
    text = strings("en")
    motion = dynamics.motion
    assert motion.stalled_at == 0.0 and motion.stall_brake is None and motion.stall is Stall.NEVER_STARTS
    assert "brake" not in dynamics.stall_warning() and "a stronger motor" in dynamics.stall_warning()
    figure = motion_plot(motion, text, "braked", resisting=dynamics.resisting)
    try:
        lower = figure.axes[-1]
        assert text["motion_resisting"].format() in legend_texts(lower) and brake_line(lower, text) is None
        # It never ran, so it did not stall: the plot says why it does not start, and where it stands.
        assert re.sub(r"\s", "", lower.get_title()) == re.sub(r"\s", "", text["motion_never_starts_title"])
        assert text["motion_rest_point"].format(angle="0") in legend_texts(lower)
    finally:
        pyplot.close(figure)
