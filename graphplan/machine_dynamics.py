"""The scene's ``[dynamics]`` worked out once for a run: the equivalent model, the flywheel and the machine's motion,
and what the command line says of their outcomes (a stall, a clutch that slips, a run off its flywheel's speed).

The drawings, the tables, the note and ``results.json`` of one run all read the one :class:`MachineDynamics`, so
that the motion is integrated once however many of them ask for it.
"""

from __future__ import annotations

import contextlib
import dataclasses
import functools
import math
import os
from collections.abc import Callable, Iterator, Mapping
from typing import TYPE_CHECKING, Any

from .errors import GraphplanError, SceneError
from .locale import strings

# The model, the flywheel and the motion are imported where they are used: the command line imports this module to
# name its type, and `graphplan --help` need not load numpy.
if TYPE_CHECKING:
    from .analysis import Analysis
    from .dynamics import ConstantSideError
    from .scene import Scene


class MachineDynamics:
    """The scene's ``[dynamics]`` worked out once for a run: the equivalent model, the flywheel it asks for
    (None without δ) and, with a motor, the machine's motion, integrated the first time it is wanted.

    ``source`` is the analysis of a linkage, or a scene without one whose ``[dynamics]`` gives load diagrams.
    """

    def __repr__(self) -> str:
        # The model's arrays made a repr of tens of thousands of characters.
        flywheel = f"JF = {self.flywheel.inertia:.5g} kg·m²" if self.flywheel is not None else "no flywheel asked for"
        motor = "a motor to integrate" if self.spec.motion is not None else "no motor"
        return f"<MachineDynamics of {self.title!r}: {flywheel}, {motor}>"

    def __init__(self, source: Analysis | Scene) -> None:
        from .dynamics import ConstantSideError, equivalent_model_of
        from .flywheel import (
            crank_omega,
            diagram_model_of,
            flywheel_from_spec,
            gear_mismatch,
            odd_synchronous_speed,
            speed_unit_slip,
        )
        from .scene import Scene

        with _scene_values("dynamics"):
            scene = source if isinstance(source, Scene) else source.scene
            self.title = scene.title
            if isinstance(source, Scene):
                self.spec = source.dynamics
                self.model = diagram_model_of(self.spec)
                self.first_position: int | None = None
            else:
                self.spec = source.scene.dynamics
                try:
                    self.model = equivalent_model_of(source, self.spec.count, constant=self.spec.constant)
                except ConstantSideError as refused:
                    raise _constant_refused(refused) from refused
                self.first_position = int(source.positions.numbers[0])
            self.flywheel = flywheel_from_spec(self.model, self.spec)
            # The motor's speed through its gear far from the machine's, which gear_warning tells: a stall's and an
            # off-design run's advice leave the gear ratio to it.
            self.gear = gear_mismatch(self.spec, crank_omega(scene.driver))
            # A Kloss motor's synchronous speed that no motor has: a stall's advice puts it first where the
            # nearest true one would give the motor more torque at rest.
            self.synchronous = odd_synchronous_speed(self.spec)
            # The mean speed typed as the crank's in the other unit: the flywheel run with is sized at the wrong
            # speed, which a stall's and an off-design run's advice put first.
            self.speed_slip = speed_unit_slip(self.spec, crank_omega(scene.driver))

    @functools.cached_property
    def motion(self):
        """The equation of motion integrated with the scene's motor (None when it names none).

        The motor replaces the constant driving moment the flywheel's balance of work assumed; the
        scene's own loads stay as they are.  A flywheel sized for δ is mounted on the driving shaft,
        so that the steady δ of the integration can be set against the δ it was sized for.
        """
        if self.spec.motion is None:
            return None
        with _scene_values("dynamics", _MOTION):
            return self._motion_spec.run(self.machine)

    def refuse(self) -> None:
        """Raise :class:`SceneError` for a motion the run could not integrate to its end (a motor that outpulls
        the resistance at every speed): found before anything is integrated, as ``check`` does."""
        if self.spec.motion is not None:
            with _scene_values("dynamics", _MOTION):
                self._motion_spec.refuse(self.machine)

    @property
    def _motion_spec(self):
        """The scene's motion with its start's angle in the run's φ: the scene gives ``start.angle_deg`` as the
        driver's ``angle_deg`` reads (the crank's own angle), and the run counts φ from the first position, where
        the equivalent model starts, in the crank's sense of rotation.  Without it the run starts there."""
        asked = self.spec.motion
        if self.first_position is None:
            # A machine known by its load diagrams has its own inertia at dynamics.inertia, a linkage its links'.
            asked = dataclasses.replace(asked, inertia_key="inertia")
        model = self.model
        if not asked.start_angle_given:
            return asked
        phi = (model.sense * (asked.start.angle - float(model.driver[0]))) % (2.0 * math.pi)
        return dataclasses.replace(asked, start=dataclasses.replace(asked.start, angle=phi))

    @functools.cached_property
    def machine(self):
        """The machine the motor drives: Je(φ) with the flywheel sized for δ, and Mr(φ) of the scene's loads."""
        import numpy as np

        from .machine_motion import Machine, PiecewiseMoment

        model = self.model
        phi = 2.0 * np.pi * np.arange(self.spec.count) / self.spec.count
        angles, moments = self.resisting
        # A load over part of the stroke makes Mr jump or turn a corner (the model gives the angle twice): the
        # integrator takes it piece by piece, where a spline through samples would ring round the jump.
        resisting = PiecewiseMoment(angles, moments) if np.any(np.diff(angles) == 0) else moments
        with _scene_values("dynamics"):
            return Machine(inertia=np.interp(phi, model.coordinate, model.inertia) + self.flywheel_inertia,
                           inertia_slope=np.interp(phi, model.coordinate, model.inertia_slope), resisting=resisting,
                           reversible=self.weights_alone)

    @property
    def weights_alone(self) -> bool:
        """Whether Mr is the moment of the weights alone (a linkage with no loads): it acts whichever way the
        shaft turns, so that at rest it turns the machine back where the brake cannot hold it."""
        model = self.model  # every scene load is on one side of the model or the other
        return self.first_position is not None and not (model.driving_loads or model.resisting_loads)

    @property
    def resisting(self):
        """Mr(φ) for the equation of motion: angles over one turn (rad) and the reduced moment of the scene's own
        loads there (N·m, positive where they resist), without the constant moment the flywheel's balance of
        work assumed in place of the motor.  Equally spaced on [0, 2π) where it is smooth; where it jumps or turns
        a corner (a load's switch, a vertex of its diagram), the model's own samples from 0 to 2π, each such
        angle given twice (:func:`~graphplan.machine_motion.moment.exact_jumps`)."""
        import numpy as np

        from .machine_motion.moment import exact_jumps

        model = self.model
        made_up = {"driving": model.driving, "resisting": model.resisting}.get(model.constant, 0.0)
        coordinate, moment = model.coordinate, -(model.moment - made_up)
        if self.first_position is None:
            coordinate, moment = _diagram_corners(coordinate, moment, self.spec.diagrams)
        angles, moments = exact_jumps(coordinate, moment)
        if np.any(np.diff(angles) == 0):
            return angles, moments
        phi = 2.0 * np.pi * np.arange(self.spec.count) / self.spec.count
        return phi, -np.interp(phi, model.coordinate, model.moment - made_up)

    @property
    def flywheel_inertia(self) -> float:
        """The flywheel mounted for the motion: the one sized for δ, or none."""
        return self.flywheel.inertia if self.flywheel is not None else 0.0

    def motion_results(self) -> dict[str, Any]:
        """The motion's part of ``results.json``: the integrator and its reason, the steady state."""
        motion = self.motion
        result: dict[str, Any] = {"method": motion.method, "method_reason": motion.method_reason,
                                  "duration": float(motion.t[-1]), "flywheel_inertia": self.flywheel_inertia,
                                  "steady": motion.steady is not None}
        steady = motion.steady
        if steady is not None:
            result.update(omega_mean=steady.mean_speed, omega_max=steady.max_speed, omega_min=steady.cycle.min_speed,
                          delta=steady.cycle.delta, steady_after=steady.reached_at,
                          start_up_time=motion.start_up_time(5.0))
        if self.spec.motion.clutch is not None:
            locked = motion.event_time("clutch locked")
            result.update(clutch_locked_at=locked, slip_energy=motion.slip_energy,
                          clutch_common_speed=None if locked is None else float(motion.state_at([locked])[1, 0]))
            if steady is not None:
                result.update(slip_energy_per_turn=motion.steady_slip_energy, slip_power=motion.steady_slip_power)
        if motion.stalled_at is not None:
            result.update(stalled_at=motion.stalled_at, stalled_at_angle_deg=self.stall_angle_deg())
        elif motion.stopped_at is not None:
            result.update(stopped_at=motion.stopped_at, stopped_at_angle_deg=self.rest_angle_deg())
        return result

    def stall_angle_deg(self) -> float | None:
        """Where the machine stalled, as the driver's ``angle_deg`` reads (:meth:`rest_angle_deg`); None where it
        did not."""
        motion = self.motion
        if motion is None or motion.stalled_at is None:
            return None
        return self.rest_angle_deg()

    def rest_angle_deg(self) -> float | None:
        """Where the machine came to rest for good (stalled, or run down with the motor off), as the driver's
        ``angle_deg`` reads (the crank's own angle, 0…360°): the run counts its angle from the first position,
        where the equivalent model starts.  None where it did not."""
        motion = self.motion
        # A machine that never starts has stalled without stopping: it was never moving.
        if motion is None or (motion.stopped_at is None and motion.stalled_at is None):
            return None
        model = self.model
        return math.degrees(float(model.driver[0]) + model.sense * float(motion.phi[-1])) % 360.0

    def stall_place(self, text: Mapping[str, str], written: Callable[[float], str]) -> str:
        """Where the machine came to rest, in words: the crank's own angle, and where the run's plots count it
        from (position 1)."""
        turned_deg = math.degrees(float(self.motion.phi[-1])) % 360.0
        crank, turned = written(self.rest_angle_deg()), written(turned_deg)
        if self.first_position is None:
            return f"{crank}°"
        return text["angle_and_turned"].format(angle=crank, turned=turned, number=self.first_position)

    def asks_kilowatts(self) -> bool:
        """Whether the stall's line asks if the motor's power was typed in kilowatts: a Kloss motor under 1000 W
        that never starts the machine, which a thousand times its torque would.  Kloss' torque grows with P: such a
        motor is one whose power was typed in kW ("4 kW" as power = 4), the likelier slip than a 4 W motor on a
        press."""
        from .machine_motion import Stall

        motion = self.motion
        if motion is None or motion.stalled_at is None or motion.stall is not Stall.NEVER_STARTS:
            return False
        power = getattr(self.spec.motion.motor, "power", None)
        mr = self.machine.mr(float(motion.phi[-1]), 0.0)
        return power is not None and power < 1000 and 1000 * motion.torque_at_rest > mr

    def stall_warning(self) -> str | None:
        """One line for the command line when the motor cannot keep the machine turning; its numbers the note's
        (:func:`~graphplan.render.numerals.number`), a clutch's and a brake's given ones too (a brake on at
        t = 0.12345 s, which the note writes 0.1235), a scene's key offered as it is typed."""
        from .machine_motion import Stall
        from .render.numerals import number

        motion = self.motion
        if motion is None or motion.stalled_at is None:
            return None
        where = self.stall_place(strings("en"), lambda value: number(value, 4))
        stalled = number(motion.stalled_at, 4)
        # Where it stands at the end of the run: where it never started, where it stood from the start.
        mr = self.machine.mr(float(motion.phi[-1]), 0.0)
        resisting = number(mr)
        stall = motion.stall
        if stall is Stall.NEVER_STARTS_CLUTCH:
            return (f"dynamics: the machine does not start: at rest at φ = {where} the clutch, slipping at its "
                    f"{number(motion.clutch.torque)} N·m, does not overcome the resistance there, {resisting} N·m (a "
                    "clutch of more torque)")
        if stall in (Stall.NEVER_STARTS, Stall.NEVER_STARTS_BRAKED):
            unmoved = (f"dynamics: the machine does not start: at rest at φ = {where} the driving torque, "
                       f"{number(motion.torque_at_rest)} N·m, does not overcome the resistance there")
            if stall is Stall.NEVER_STARTS:
                power = getattr(self.spec.motion.motor, "power", None)
                in_kilowatts = (f"; power = {power:g} W: kilowatts typed for watts? (the scene's power is in W, "
                                f"{power:g} kW is power = {power * 1000:g})" if self.asks_kilowatts() else "")
                # At rest the shaft gets u·M(0): a ratio typed the wrong way up (the shaft's speed over the motor's)
                # gives it u² of what 1/u would, and is asked about where 1/u would start the machine.  Where the gear
                # line (self.gear) tells the ratio that fits the machine's speed, and the advice points to it, the
                # question would give that ratio a second time: it is asked only of a motor the gear line cannot
                # weigh (one of no speed of its own, a constant torque) or whose speed the ratio fits either way up.
                u = self.spec.motion.motor.gear_ratio
                inverted = (f"; gear_ratio = {u:g} turns the shaft faster than the motor: the ratio inverted? (it is "
                            f"the motor's speed over the shaft's: 1/{u:g} = {1 / u:.4g})"
                            if u < 1 and self.gear is None and motion.torque_at_rest / u ** 2 > mr else "")
                return (f"{unmoved}, {resisting} N·m ({self.stall_advice('or a start from another angle')})"
                        f"{in_kilowatts}{inverted}")
            held = motion.brake.torque
            return (f"{unmoved} and the brake applied at t = {number(motion.brake.at, 4)} s, {resisting} + "
                    f"{number(held)} = {number(mr + held)} N·m: the brake's torque (dynamics.brake.torque) holds the "
                    "machine from the start (a later dynamics.brake.at, after the start-up, or a smaller brake torque)")
        if stall is Stall.CLUTCH:
            return (f"dynamics: the machine stalls at t = {stalled} s, φ = {where}: the clutch, "
                    f"slipping at its {number(motion.clutch.torque)} N·m, cannot carry it past the resistance "
                    f"there, {resisting} N·m (a clutch of more torque)")
        if stall is Stall.BRAKE_CLUTCH:
            return (f"dynamics: the brake applied at t = {number(motion.brake.at, 4)} s brings the machine to rest "
                    f"at t = {stalled} s, φ = {where}, where the clutch, slipping at its "
                    f"{number(motion.clutch.torque)} N·m, cannot turn it against the brake's "
                    f"{number(motion.brake.torque)} N·m and the resistance there, {resisting} N·m (a smaller "
                    "dynamics.brake.torque keeps it turning; dynamics.motor.off_at switches the motor off to stop it)")
        if stall is Stall.BRAKE:
            return (f"dynamics: the brake applied at t = {number(motion.brake.at, 4)} s brings the machine to rest "
                    f"at t = {stalled} s, φ = {where}, and the motor stalls: it cannot turn the machine "
                    f"against the brake's {number(motion.brake.torque)} N·m and the resistance there, {resisting} N·m "
                    "(a smaller dynamics.brake.torque keeps it turning; dynamics.motor.off_at switches the motor off "
                    "to stop it)")
        return (f"dynamics: the machine stalls at t = {stalled} s, φ = {where}: the motor cannot carry it past the "
                f"resistance there ({self.stall_advice('or a start unloaded through a clutch')})")

    def synchronous_torques_at_rest(self) -> tuple[float, float] | None:
        """The motor's torque at rest on the driving shaft as given and with the nearest true synchronous speed,
        where the scene's synchronous_rpm is none and the true one gives more (:mod:`graphplan.flywheel`'s
        :class:`~graphplan.flywheel.OddSynchronousSpeed`); None otherwise."""
        return None if self.synchronous is None else self.synchronous.torques_at_rest()

    def stall_advice(self, last: str) -> str:
        """What lets a machine the motor stalls run, ending with ``last``: a larger gear ratio (more torque on the
        shaft) where the gear fits the speed; where :func:`~graphplan.flywheel.gear_warning` tells the ratio, not
        one it already says is too large, nor again the larger one it gives with its number.  A synchronous speed no
        motor has that starves the motor of torque at rest (a rated 1450 typed for 1500) is named first: a stronger
        motor would be bought for a slip mistyped."""
        from .render.numerals import number

        torques = self.synchronous_torques_at_rest()
        first = ""
        slip = self.speed_slip
        if slip is not None:
            size = "large" if slip.ratio < 1 else "small"
            first = (f"first the mean speed told for {slip.where}.{slip.key}: the flywheel run with, sized at "
                     f"{number(slip.sized)} rad/s, is some {slip.times_off ** 2:.0f} times too {size}; then ")
        elif torques is not None:
            odd = self.synchronous
            first = (f"first the synchronous speed told for {odd.where}.motor.synchronous_rpm: at "
                     f"{number(odd.nearest)} rpm the motor gives the shaft {number(torques[1])} N·m at rest, not "
                     f"{number(torques[0])}; then ")
        gear = self.gear
        if gear is None:
            return f"{first}a stronger motor, a larger gear ratio, {last}"
        if gear.too_large:
            return (f"{first}a stronger motor, {last}; not a larger gear ratio: {gear.where}.motor.gear_ratio = "
                    f"{gear.gear_ratio:g} already turns the shaft well below the machine's speed")
        return f"{first}the gear ratio told for {gear.where}.motor.gear_ratio, a stronger motor, {last}"

    def slipping_warning(self) -> str | None:
        """One line for the command line when the clutch slips in every steady turn: it cannot pass the peaks of
        the resistance, and wears for as long as the machine runs."""
        from .render.numerals import number

        motion = self.motion
        if motion is None or not motion.steady_slip_energy:
            return None
        return (f"dynamics: the clutch slips in every steady turn, losing {number(motion.steady_slip_energy)} J a turn "
                f"({number(motion.steady_slip_power)} W): its {number(self.spec.motion.clutch.torque)} N·m cannot pass "
                "the resistance's peaks (a clutch of more torque)")

    def unsettled_warning(self) -> str | None:
        """One line for the command line when a run with the motor on ends short of a steady state: the results
        then have no ωm, δ or start-up time, which only the note said (a machine of great inertia still speeding
        up after its 2000 turns' time)."""
        from .machine_motion.simulation import MOST_CYCLES
        from .render.numerals import number

        motion, asked = self.motion, self.spec.motion
        if (motion is None or motion.steady is not None or motion.stalled_at is not None or motion.stopped_at is not None
                or asked.motor_off_at is not None):
            return None
        end, speed = float(motion.t[-1]), float(motion.omega[-1])
        limit = "its duration" if asked.duration is not None else f"{MOST_CYCLES} turns' time at the running speed"
        # Written as every number on the console is: a heavy machine's 2000 turns' time read "t = 1.257e+04 s".
        head = f"dynamics: no steady state within the run, t = {number(end)} s ({limit}): "
        runaway = self.runaway()
        if runaway is not None:
            # The torques as the note's runaway line writes them.
            return (head + f"the machine speeds up without end, at ω = {number(speed)} rad/s by then: the motor's "
                    f"torque on the shaft, {number(runaway[0])} N·m, exceeds the mean resistance, "
                    f"{number(runaway[1])} N·m, at every speed, so no duration reaches a steady state (more "
                    "resistance, or a motor whose torque falls with speed: linear, kloss)")
        return (head + f"the machine is still {'speeding up' if self.speeding_up() else 'slowing down'} at "
                f"ω = {number(speed)} rad/s, so the results have no ωm, δ or start-up time; a longer [dynamics] "
                "duration (s) runs it on")

    def runaway(self) -> tuple[float, float] | None:
        """(the motor's torque on the shaft, the mean resistance) where the motor, on to the run's end with no
        brake, outpulls the resistance at every speed: the machine speeds up without end (a run given a duration
        ends at it); None otherwise."""
        from .machine_motion.method import speeds_up_without_end

        asked = self.spec.motion
        if self.motion is None or asked.motor_off_at is not None or asked.brake is not None:
            return None
        return speeds_up_without_end(self.machine, asked.motor)

    def speeding_up(self) -> bool:
        """Whether the run ends speeding up, on the average over whole turns: the last turn's mean speed against
        the one before it (within a turn the speed rises and falls with the resistance, so two instants say
        nothing); short of two turns, the speed at the end against the mean over the run."""
        motion = self.motion
        cycles = motion.cycles
        if len(cycles) >= 2:
            return cycles[-1].mean_speed >= cycles[-2].mean_speed
        travel, span = float(motion.phi[-1] - motion.phi[0]), float(motion.t[-1] - motion.t[0])
        return span <= 0 or float(motion.omega[-1]) >= travel / span

    def off_design(self) -> tuple[float, float] | None:
        """(the steady mean speed, the speed the flywheel was sized at), rad/s, where the motor settles the machine
        more than :data:`OFF_DESIGN` away from the speed its flywheel was sized at, which the command line's line and
        the note's caution tell; None where it settles near it, or there is no steady run or no flywheel."""
        motion, flywheel = self.motion, self.flywheel
        if motion is None or motion.steady is None or flywheel is None or flywheel.inertia <= 0:
            return None
        settled, sized = motion.steady.mean_speed, flywheel.omega_mean
        return None if abs(settled - sized) <= OFF_DESIGN * sized else (settled, sized)

    def off_design_warning(self) -> str | None:
        """One line for the command line when the motor settles the machine away from the speed its flywheel
        was sized at (more than :data:`OFF_DESIGN` apart): δ then differs from the one asked for.  The speeds and δ
        are written as the note writes them (ωm = 10.210, δ = 0.02350): the console's 10.21 beside the note's 10.210
        read as two numbers."""
        off = self.off_design()
        if off is None:
            return None
        motion, flywheel = self.motion, self.flywheel
        settled, sized = off
        from .render.dynamics import flywheel_numbers
        from .render.numerals import number, steady_delta, worked_out

        # A gear ratio far off the machine's speed is told on its own line, with the ratio that fits: this one
        # names it and leaves the advice to that line.
        gear, slip = self.gear, self.speed_slip
        through = "" if gear is None else f"through {gear.where}.motor.gear_ratio = {gear.gear_ratio:g} "
        advice = "" if gear is not None else \
            f" (the mean speed told for {slip.where}.{slip.key} first)" if slip is not None else \
            " (a motor, gear ratio or speed that agree with each other)"
        return (f"dynamics: {through}the motor runs the machine at ωm = {worked_out(settled)} rad/s, "
                f"{abs(settled / sized - 1):.0%} off the {flywheel_numbers(self.model, flywheel).omega_mean} rad/s its "
                f"flywheel was sized at for δ = {number(flywheel.delta)}; steady, δ = "
                f"{steady_delta(motion.steady.cycle.delta)}{advice}")


# The share by which the steady speed may differ from the one the flywheel was sized at before a run warns.
OFF_DESIGN = 0.05


def _diagram_corners(coordinate, moment, diagrams):
    """A load diagram's samples with each vertex given once put in twice, a corner of Mr (a jump of nought), as a
    linkage's model puts in a load's corners: a spline through the vertex rings round it (a triangle's 300 N·m peak
    splined to 299.27 N·m half a degree off it, where the diagram gives 298.89), and the steady δ moved in its fourth
    digit.  The turn's ends are vertices too: the diagram's slope need not go on across 0."""
    import numpy as np

    vertices = np.unique(np.concatenate([np.radians(diagram.angles_deg) for diagram in diagrams]))
    near = np.abs(coordinate[:, None] - vertices[None, :]) <= 1e-9
    once = np.flatnonzero(near.sum(axis=0) == 1)
    where = [int(np.flatnonzero(near[:, k])[0]) for k in once]
    return np.insert(coordinate, where, coordinate[where]), np.insert(moment, where, moment[where])


def _constant_refused(refused: ConstantSideError) -> SceneError:
    """``[dynamics] constant`` naming a side the scene gives loads on, refused at that key with the ways out that
    work: ``"none"``, the other side only where the scene gives no loads on it too (it was offered where it did,
    and was refused in its turn), or the loads left out."""
    loads = ", ".join(refused.loads)
    ways = " or ".join(f'constant = "{way}"' for way in refused.ways_out)
    both = " (the scene gives loads of both sides)" if len(refused.ways_out) == 1 else ""
    return SceneError("dynamics.constant", f"would take the {refused.constant} {refused.noun} constant in place of "
                      f"the scene's {refused.constant} loads ({loads}): write {ways}{both}, or leave {loads} out",
                      refused.constant)


# What each step of the dynamics works out, and the keys of the scene that feed it, for an error a library raises
# there: numpy's or scipy's words alone ("The function value at x=-0.0 is NaN") read as the project's and named no
# value of the scene to change.
_MODEL = ("working out the equivalent model and the flywheel",
          ("the load diagrams or the linkage's loads and masses, inertia, rpm or omega, delta, flywheel_shaft_rpm, "
           "count"))
_MOTION = ("integrating the machine's motion",
           "motor, brake, clutch, start, duration, method, rtol, steady_tolerance, with the model's inertia and loads")


@contextlib.contextmanager
def _scene_values(where: str, step: tuple[str, str] = _MODEL) -> Iterator[None]:
    """The dynamics' own refusals of the values they are given (Je that vanishes, work that does not balance, an
    integration that cannot go on) as the scene's errors at ``where``: they are what the scene asked for.  An error a
    library raises instead (its message is its own, not the project's) is told as what ``step`` was doing when it
    stopped and which keys feed it, with the library's words quoted as its."""
    try:
        yield
    except GraphplanError:
        raise
    except (ValueError, ArithmeticError) as error:
        library = _library_of(error)
        if library is None:
            raise SceneError(where, str(error)) from error
        doing, keys = step
        raise SceneError(where, f"{doing} stopped in {library} ({type(error).__name__}: \"{error}\"): a value of the "
                         f"scene lies beyond what it can be worked out with; check {where}'s {keys}") from error


def _library_of(error: BaseException) -> str | None:
    """The package outside graphplan whose code raised ``error`` (numpy, scipy), or None where graphplan's did."""
    package = os.path.dirname(os.path.abspath(__file__))
    frame = error.__traceback__
    while frame is not None and frame.tb_next is not None:
        frame = frame.tb_next
    if frame is None:
        return None
    filename = os.path.abspath(frame.tb_frame.f_code.co_filename)
    if filename.startswith(package + os.sep):
        return None
    name = frame.tb_frame.f_globals.get("__name__", "")
    return name.partition(".")[0] or "a library"
