"""The report figure of the machine's motion in time: start-up, steady state, run-down.

The upper plot is the driving shaft's speed over the whole run (and the clutch's driving half,
when there is a clutch), with the events of the run (motor off, brake on, clutch locked, ...)
and the band of the steady state; the lower plot is the speed over the last steady turn against
the crank angle, beside the flywheel's estimate from the energy–mass diagram; where the machine
stalls, the moments on the shaft over the angle it turned, the motor's falling short of Mr(φ), or of Mr(φ) + Mt from
where a brake that brought it to rest, or held it from the start, was applied.  Every word comes
from the locale (``motion_`` keys).  matplotlib is imported only inside :func:`motion_figure`.
"""

from __future__ import annotations

import math
from collections.abc import Mapping

import numpy as np

from ..locale import Count
from ..machine_motion import MachineMotion
from ..render.numerals import number, steady_delta, worked_out
from ..render.primitives import FONT_SIZE_PER_CAP
from ..render.wrapping import fitted
from .plot_style import (
    CRANK_TICK_DEG,
    PAGE_WIDTH_INCHES,
    legend_under,
    new_figure,
    settings,
    svg_text,
    with_decimal_mark,
)

# Points of the dense solution drawn over the run, besides the solver's own steps: enough for a
# smooth fluctuation at a few hundred turns.
_RUN_SAMPLES = 6000
_TURN_SAMPLES = 721
_SHAFT, _DRIVING_HALF, _FLYWHEEL, _EVENT, _BRAKE = "#1f4e79", "#a83a1f", "#1f7a3a", "#555555", "#6a2c91"
# The width a plot's title and words may take (mm): its axes' on the figure (PAGE_WIDTH_INCHES), less a margin.
_WORDS_MM = 130.0
_MM_PER_POINT = 25.4 / 72.0
# The legends' columns, each under its plot (inside a plot no corner is clear: the run's legend would hide part of
# a run-down or a start-up, the stall's a resistance that swings over the turn and a brake's curve above it).  The
# stall's entries are long sentences, one to a line.
_RUN_COLUMNS, _TURN_COLUMNS, _STALL_COLUMNS = 2, 2, 1
# The two plots' figure before the legends under them (inches), by whether the lower one is the steady turn: the
# legends then add their room, and the whole stays within the 230 mm the note gives a figure on its page (html.py,
# word.py), which would otherwise shrink it, words and all; the stall's legend, a sentence a line, takes the most.
_TWO_PLOTS_HEIGHT = {True: 8.0, False: 7.75}


def motion_figure(motion: MachineMotion, text: Mapping[str, str], title: str = "",
                  flywheel: tuple[np.ndarray, np.ndarray] | None = None,
                  resisting: tuple[np.ndarray, np.ndarray] | None = None, *,
                  stall_angle_deg: float | None = None) -> str:
    """The SVG text of :func:`motion_plot`."""
    import matplotlib

    with matplotlib.rc_context(settings()):
        return svg_text(motion_plot(motion, text, title, flywheel, resisting, stall_angle_deg=stall_angle_deg))


def motion_plot(motion: MachineMotion, text: Mapping[str, str], title: str = "",
                flywheel: tuple[np.ndarray, np.ndarray] | None = None,
                resisting: tuple[np.ndarray, np.ndarray] | None = None, *, stall_angle_deg: float | None = None):
    """The motion's matplotlib figure: the run above, the steady turn below (or only why the machine
    stands still, where it never moves).

    ``flywheel`` is the flywheel's estimate of the steady speed over the turn: the crank angles
    (rad, from the first position) and ω there, drawn beside the integrated steady turn.
    ``resisting`` is Mr(φ) over one turn (the angles, rad, in the run's φ, and N·m): where the machine
    stalls, the lower plot sets it against the motor's torque along the run, over the angle turned from
    the start, to show where the motor falls short; where the clutch slipped as it stalled, against the
    clutch's capacity too; where the run's brake holds it where it stands
    (:attr:`~graphplan.machine_motion.MachineMotion.stall_brake`), against Mr(φ) + Mt from where the brake was
    applied on, and the title names the brake.  ``stall_angle_deg`` is where it stalled as the scene counts the
    crank's angle (the motion's own φ within its turn where not given).
    """
    stall_deg = stall_angle_deg if stall_angle_deg is not None else motion.stalled_at_angle_deg
    import matplotlib

    with matplotlib.rc_context(settings()):
        below = motion.steady is not None or (motion.stalled_at is not None and resisting is not None)
        run_down = motion.stalled_at is None and motion.stopped_at is not None
        # Each plot with a legend under it, and the legend's columns: placed once the figure is laid out.
        legends = []
        if _moved(motion) and not below:
            # A run-down, or a run with no steady state: the speed in time says it all, no empty half below.
            figure = new_figure(figsize=(PAGE_WIDTH_INCHES, 5.5))
            run = figure.subplots(1, 1)
            _speed_over_time(run, motion, text)
            legends.append((run, _RUN_COLUMNS))
            if not run_down:
                why = _why_not_steady(motion, text, stall_deg)
                run.set_title(_broken(f"{run.get_title()}: {why}" if run.get_title() else why, 10), fontsize=10)
        else:
            if _moved(motion):
                figure = new_figure(figsize=(PAGE_WIDTH_INCHES, _TWO_PLOTS_HEIGHT[motion.steady is not None]))
                run, turn = figure.subplots(2, 1, height_ratios=(3, 2))
                _speed_over_time(run, motion, text)
                legends.append((run, _RUN_COLUMNS))
            else:
                # A speed zero throughout is an empty plot along its axis: only why it stands still is drawn.
                figure = new_figure(figsize=(PAGE_WIDTH_INCHES, 4.5))
                turn = figure.subplots(1, 1)
            if motion.steady is not None:
                _steady_turn(turn, motion, text, flywheel)
                # Under the plot, as the run's: "best" put it on the flywheel's estimate where no corner was clear of
                # the two curves.
                legends.append((turn, _TURN_COLUMNS))
            elif motion.stalled_at is not None and resisting is not None:
                _stall(turn, motion, text, resisting, stall_deg)
                legends.append((turn, _STALL_COLUMNS))
            else:
                turn.set_axis_off()
                turn.text(0.5, 0.5, _broken(_why_not_steady(motion, text, stall_deg), 10), ha="center", va="center",
                          transform=turn.transAxes)
        with_decimal_mark(figure, text["decimal_mark"])
        # After the decimal mark, and no mathtext: the title quotes the scene's, which is the user's text (a title
        # "$5 to $10" was set in italics, and "$\frac$" stopped the run).
        figure.suptitle(text["motion_title"].format(title=title) if title else text["motion_title_plain"],
                        fontsize=11, parse_math=False)
        # Laid out last, with the suptitle and the decimal mark (the legends' own numbers carry it already): each
        # legend dropped below its abscissa's numbers and name as they came out, where a share of the plot's height
        # put it on them under a short plot or a long name; the figure grows by just their room.
        for plot, columns in legends:
            legend_under(figure, plot, fontsize=7, ncol=columns, keep_heights=True)
        if not legends:
            figure.tight_layout()
    return figure


def _why_not_steady(motion: MachineMotion, text: Mapping[str, str], stall_deg: float | None) -> str:
    """Why a run has no steady turn to draw: none reached in the run, or where the machine stalled."""
    if motion.stalled_at is None:
        return text["motion_no_steady"]
    mark = text["decimal_mark"]
    brake = motion.stall_brake
    return text[f"motion_{motion.stall.value}"].format(time=number(motion.stalled_at, 4, mark),
                                                       angle=number(stall_deg, 4, mark),
                                                       at=number(brake.at, 4, mark) if brake is not None else "")


def _broken(words: str, points: float) -> str:
    """``words`` at a font size of ``points`` broken into lines as wide as a plot: by their width on the paper, so
    that Chinese, twice as wide a character, breaks as soon."""
    cap_mm = points * _MM_PER_POINT / FONT_SIZE_PER_CAP
    return "\n".join(fitted(words, _WORDS_MM, cap_mm))


def _moved(motion: MachineMotion) -> bool:
    """Whether the shaft, or the clutch's driving half, turned at all in the run."""
    speeds = motion.omega if motion.driving_omega is None else np.concatenate((motion.omega, motion.driving_omega))
    return bool(np.any(speeds != 0.0))


def _speed_over_time(plot, motion: MachineMotion, text: Mapping[str, str]) -> None:
    end = float(motion.t[-1])
    times = np.union1d(np.linspace(float(motion.t[0]), end, _RUN_SAMPLES), motion.t)
    state = motion.state_at(times)
    # A shaft held at rest while its clutch's driving half spins up runs along ω = 0, the axes' frame, whose line hid
    # it (named in the legend and seen nowhere): drawn over the frame.
    over_the_frame = {"zorder": 2.6, "clip_on": False} if not np.any(state[1]) else {}
    plot.plot(times, state[1], color=_SHAFT, linewidth=0.9, label=text["motion_shaft"], **over_the_frame)
    if motion.driving_omega is not None:
        plot.plot(times, state[2], color=_DRIVING_HALF, linewidth=0.9, linestyle="--",
                  label=text["motion_driving_half"])
    steady = motion.steady
    mark = text["decimal_mark"]
    if steady is not None:
        cycle = steady.cycle
        # The band runs from where the steady state was reached to the first switch after it (a run-down).
        until = min([when for when, _ in motion.events if when > steady.reached_at] + [end])
        plot.fill_between([steady.reached_at, until], cycle.min_speed, cycle.max_speed, color=_FLYWHEEL, alpha=0.15,
                          linewidth=0, label=text["motion_steady_band"].format(low=_worked_out(cycle.min_speed, mark),
                                                                               high=_worked_out(cycle.max_speed, mark)))
        started = motion.start_up_time(5.0)
        if started is not None:
            plot.axvline(started, color=_FLYWHEEL, linewidth=0.8, linestyle="-.",
                         label=text["motion_start_up"].format(time=number(started, 4, mark)))
    top = float(np.nanmax(state[1:3] if motion.driving_omega is not None else state[1]))
    _events(plot, motion, text, end - float(motion.t[0]))
    plot.set_xlim(float(motion.t[0]), end)
    plot.set_ylim(bottom=min(0.0, float(np.nanmin(state[1]))), top=top * 1.08 if top > 0 else None)
    plot.set_xlabel(text["motion_time_axis"])
    plot.set_ylabel(text["motion_speed_axis"])
    plot.set_title(text["motion_run"], fontsize=10)
    plot.grid(True, linewidth=0.3)


# A clutch that slips again this many times after it first locks (every turn, where it cannot pass the resistance's
# peaks) has its slips and locks summed up in one line of the legend: listed one by one they crowd out the plot.
_REPEATS_LISTED = 2


def _events(plot, motion: MachineMotion, text: Mapping[str, str], span: float) -> None:
    """Each event a dotted line numbered at the top; the numbers are explained in the legend.

    Events close in time step their numbers down, so that they do not print over each other.  A clutch that
    slips and locks again more than :data:`_REPEATS_LISTED` times is one numbered entry from its first slip after
    locking, its lines drawn faint and unnumbered.
    """
    mark = text["decimal_mark"]
    events = list(motion.events)
    first_lock = next((k for k, (_, name) in enumerate(events) if name == "clutch locked"), None)
    again = [] if first_lock is None else [k for k, (_, name) in enumerate(events)
                                             if k > first_lock and name in ("clutch slips", "clutch locked")]
    slips = [k for k in again if events[k][1] == "clutch slips"]
    summed = set(again[again.index(slips[0]):]) if len(slips) > _REPEATS_LISTED else set()
    level, last, ordinal = 0, -math.inf, 0
    for k, (when, name) in enumerate(events):
        if k in summed and k != slips[0]:
            plot.axvline(when, color=_EVENT, linewidth=0.3, linestyle=":", alpha=0.5)
            continue
        ordinal += 1
        level = level + 1 if when - last < 0.04 * span else 0
        last = when
        plot.axvline(when, color=_EVENT, linewidth=0.6, linestyle=":")
        # Left of its line at the plot's right edge (a stall ends the run), else right of it.
        aside = -8 if when >= float(motion.t[-1]) - 0.02 * span else 2
        plot.annotate(str(ordinal), (when, 1.0), xycoords=("data", "axes fraction"), xytext=(aside, -10 - 10 * (level % 4)),
                      textcoords="offset points", fontsize=7, color=_EVENT)
        if k in summed:
            label = text["motion_event_slips_again"].format(number=ordinal, count=Count(len(slips)),
                                                            start=number(when, 4, mark),
                                                            end=number(events[max(summed)][0], 4, mark))
        else:
            words = text.get(f"motion_event_{name.replace(' ', '_')}", name)
            label = text["motion_event"].format(number=ordinal, event=words, time=number(when, 4, mark))
        plot.plot([], [], " ", label=label)


def _within_turn(angles: np.ndarray, speeds: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """A turn's angles (degrees, rising over 360°) and speeds, the angles taken within 0…360°.

    The steady turn starts where the run started, plus whole turns: a run started away from position 1 has its
    turn run from there (180…540° for a start at 180°).  The part past 360° is drawn from 0°, the curve broken
    where it wraps, with the speed at 360° (= 0°) at both ends of the break."""
    angles = angles - 360.0 * math.floor(angles[0] / 360.0 + 1e-9)
    past = angles > 360.0 * (1.0 + 1e-12)
    if not np.any(past):
        return angles, speeds
    wrapped = np.where(past, angles - 360.0, angles)
    i = int(np.argmax(past))
    at_edge = float(np.interp(360.0, angles[i - 1:i + 1], speeds[i - 1:i + 1]))
    return (np.concatenate([wrapped[:i], [360.0, np.nan, 0.0], wrapped[i:]]),
            np.concatenate([speeds[:i], [at_edge, np.nan, at_edge], speeds[i:]]))


def _steady_turn(plot, motion: MachineMotion, text: Mapping[str, str],
                 flywheel: tuple[np.ndarray, np.ndarray] | None) -> None:
    cycle, mark = motion.steady.cycle, text["decimal_mark"]
    times = np.linspace(cycle.start, cycle.start + cycle.period, _TURN_SAMPLES)
    state = motion.state_at(times)
    angles, speeds = _within_turn(np.degrees(state[0]), state[1])
    plot.plot(angles, speeds, color=_SHAFT, linewidth=1.1,
              label=text["motion_integrated"].format(delta=steady_delta(cycle.delta).replace(".", mark)))
    if flywheel is not None:
        along, omega = flywheel
        estimate = (float(np.max(omega)) - float(np.min(omega))) / (0.5 * (float(np.max(omega)) + float(np.min(omega))))
        plot.plot(np.degrees(along), omega, color=_FLYWHEEL, linewidth=0.9, linestyle="--",
                  label=text["motion_flywheel"].format(delta=number(estimate, 4, mark)))
    for value in (cycle.max_speed, cycle.min_speed):
        plot.axhline(value, color=_EVENT, linewidth=0.5, linestyle=":")
    if cycle.max_speed == cycle.min_speed and flywheel is None:
        # A uniform turn: left to itself the axis would stretch the start-up's last creep, 10⁻⁹ of ω, over its
        # height, as if the speed swung.
        half = 0.005 * abs(cycle.max_speed)
        plot.set_ylim(cycle.max_speed - half, cycle.max_speed + half)
    plot.set_xlim(0.0, 360.0)
    plot.set_xticks(np.arange(0.0, 361.0, CRANK_TICK_DEG))
    plot.set_xlabel(text["motion_angle_axis"])
    plot.set_ylabel(text["motion_speed_axis"])
    plot.set_title(text["motion_turn"].format(time=number(cycle.start, 4, mark)), fontsize=10)
    plot.grid(True, linewidth=0.3)


def _stall(plot, motion: MachineMotion, text: Mapping[str, str], resisting: tuple[np.ndarray, np.ndarray],
           stall_deg: float) -> None:
    """The moments on the driving shaft over the angle it turned before it stalled: the motor's torque
    along the run against the resisting forces' Mr(φ), the stall where the motor's falls short (where the
    clutch slipped, the clutch's capacity, which falls short first; where the brake holds the machine, Mr(φ) + Mt
    from where it was applied on: the motor's may stand above Mr alone)."""
    mark = text["decimal_mark"]
    angles, moments = resisting
    # Counted from the start, as the axis says: the run's own φ counts from the first position.
    start = float(motion.phi[0])
    turned = np.degrees(motion.phi - start)
    end = float(turned[-1])
    # The whole turn the stall is in, from the start: where Mr rises past the motor is plain to see.
    right = 360.0 * max(math.floor(end / 360.0) + 1.0, 1.0)
    along = np.linspace(0.0, right, max(_TURN_SAMPLES, int(right) * 2 + 1))

    # Wrapped into the samples' turn by hand: np.interp's period takes 2π as 0 and sorts the samples again, which
    # may swap the two values given at a jump's angle (Mr drawn slanting into the jump from the sample before it).
    closed = angles[-1] >= angles[0] + 2.0 * np.pi
    turn_angles = angles if closed else np.append(angles, angles[0] + 2.0 * np.pi)
    turn_moments = moments if closed else np.append(moments, moments[0])

    def resisting_at(turned_deg: np.ndarray) -> np.ndarray:
        phi = angles[0] + np.mod(start + np.radians(turned_deg) - angles[0], 2.0 * np.pi)
        return np.interp(phi, turn_angles, turn_moments)

    plot.plot(along, resisting_at(along), color=_DRIVING_HALF, linewidth=1.0, label=text["motion_resisting"].format())
    brake = motion.stall_brake
    if brake is not None:
        # The brake's torque joins Mr where it came on, a step up from Mr there; on from the start (where the machine
        # never turned), it is there all along.
        if brake.at <= float(motion.t[0]):
            drawn, total = along, resisting_at(along) + brake.torque
        else:
            on = math.degrees(float(motion.state_at([brake.at])[0, 0]) - start)
            after = np.concatenate(([on], along[along > on]))
            drawn = np.concatenate(([on], after))
            total = np.concatenate((resisting_at(after[:1]), resisting_at(after) + brake.torque))
        plot.plot(drawn, total, color=_BRAKE, linewidth=1.3,
                  label=text["motion_resisting_braked"].format(torque=number(brake.torque, 4, mark),
                                                               at=number(brake.at, 4, mark)))
    held = float(motion.motor_torque[-1])
    if motion.turned:
        plot.plot(turned, motion.motor_torque, color=_SHAFT, linewidth=1.1, label=text["motion_motor_torque"].format())
    elif motion.stalled_slipping:
        # The shaft never turned behind a slipping clutch: the motor drove the clutch's driving half alone, and the
        # shaft took the clutch's torque, drawn below; the motor's along the run was a line of no length at 0°.
        pass
    else:
        # A shaft that never turned holds the motor at rest, at its starting torque, wherever it stands: drawn along
        # the run it was a line of no length at 0°, named in the legend and seen nowhere; across the turn it shows
        # where a start from another angle would go.
        plot.plot(along, np.full_like(along, held), color=_SHAFT, linewidth=1.1,
                  label=text["motion_motor_torque_at_rest"].format())
    if motion.stalled_slipping:
        held = motion.clutch.torque
        plot.axhline(held, color=_FLYWHEEL, linewidth=1.0, linestyle="--",
                     label=text["motion_clutch_capacity"].format(torque=number(held, 4, mark)))
    # A machine that never started did not stall after a run: it stands where it stood.
    point = text["motion_stall_point"] if motion.turned else text["motion_rest_point"]
    plot.plot([end], [held], "o", color=_SHAFT, markersize=4,
              label=point.format(turned=number(end, 4, mark), angle=number(stall_deg, 4, mark),
                                 time=number(motion.stalled_at, 4, mark)))
    plot.axhline(0.0, color=_EVENT, linewidth=0.5)
    plot.set_xlim(0.0, right)
    plot.set_xticks(np.arange(0.0, right + 1.0, CRANK_TICK_DEG * max(1, round(right / 360.0))))
    plot.set_xlabel(text["motion_turned_axis"])
    plot.set_ylabel(text["motion_moment_axis"])
    plot.set_title(_broken(text["motion_stall_title" if motion.turned else "motion_never_starts_title"], 10),
                   fontsize=10)
    plot.grid(True, linewidth=0.3)


def _worked_out(value: float, mark: str) -> str:
    """A speed of the steady run as the note writes it (its noughts kept: ωmin = 10.210), with the locale's mark: the
    legend wrote four digits, 10.21, beside the note's 10.210."""
    return worked_out(value).replace(".", mark)


__all__ = ["motion_figure", "motion_plot"]
