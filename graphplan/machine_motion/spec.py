"""The motion's keys of the scene's ``[dynamics]`` table, read into a :class:`MotionSpec` that runs them."""

from __future__ import annotations

import contextlib
import math
from collections.abc import Iterator, Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..errors import SceneError
from ..flywheel import FASTEST_MEAN_RPM, misplaced_keys
from ..reader import Table, check_number
from ..units import RPM, exponent_slip, motor_speed_in_rpm, percentage_question, rpm_question
from .drive import MOTOR_KINDS, REST, Brake, Clutch, ConstantTorque, KlossMotor, LinearMotor, Motor, Start
from .method import (
    EndlessRun,
    refuse_endless_run_down,
    refuse_runaway,
    runaway_time_to,
    running_speed,
    speeds_up_without_end,
)
from .shaft import TWO_PI, Machine
from .simulation import (
    DEFAULT_RTOL,
    LARGEST_STEADY_TOLERANCE,
    METHODS,
    MOST_CYCLES,
    SMALLEST_RTOL,
    MachineMotion,
    simulate,
)

# The most turns of the shaft a scene's run integrates: a start-up and a steady state take tens to hundreds; a
# duration of many more is a slip of the unit, and would hold the run for hours.
MOST_TURNS = 100_000
# The shortest time constant J/c a brake's damping may give, as a share of a turn's period at the running speed.  A
# damping far stiffer stops the shaft within a sliver of a turn and then lets it creep at (Md − Mr)/c: a rigid stop
# the run cannot integrate turn by turn (a hundred-thousandth of the period took a minute and then gave up).
SHORTEST_BRAKE_TIME_CONSTANT = 0.01
# The shortest time a clutch's torque may take to run the machine's side, its inertia at its least, from rest up to
# the running speed, J·ω/Tc, as a share of a turn's period.  A friction clutch brings a machine to speed over some
# tenths of a second, a good part of a turn or many; a side that comes to speed within a ten-thousandth of a turn has
# next to no inertia beside its clutch (1e-14 kg·m² typed for the machine's), and its slip ends within the rounding
# of the run's clock, where the integrator could take no step (scipy's "`ts` must be strictly increasing").
SHORTEST_CLUTCH_SPIN_UP = 1e-4
# The overload capacity λ = Mmax/MN a Kloss motor may have: catalogues give 1.6 to 3.5 (crane motors some 4), so one
# of 10 or more is no induction motor, most likely the percentage (220 for λ = 2.2) typed for the ratio.
LARGEST_OVERLOAD = 10.0
# The motor's speed over the driving shaft's, u.  A ratio no gear has (1e12, or 1e-12, a slip of the exponent) ran
# without a word: the shaft turned at the motor's speed over u, and the rotor's inertia came to it times u².  The
# strongest reducers a machine is driven through, a multi-stage worm gear's or a slewing drive's, reach some 1:10 000;
# the fastest step-up gears, a centrifuge's or a wind turbine's generator's, some 100:1.
SMALLEST_GEAR_RATIO = 0.001
LARGEST_GEAR_RATIO = 100_000.0
# A Kloss motor's rated power (W): the smallest induction motors, a fan's shaded-pole ones, give a few watts, the
# largest, a compressor station's or a rolling mill's, some tens of megawatts.  Kloss' torques follow P, so
# power = 1e-12 gave a motor of no torque, and a stall told as the motor's weakness.
SMALLEST_MOTOR_POWER = 1.0
LARGEST_MOTOR_POWER = 1e9
# A motor's speeds (rev/min): its synchronous and rated speeds, a linear one's no-load speed and its points'.  The
# slowest motors, low-speed hydraulic ones and many-poled induction ones, turn at some tens of rev/min; the fastest,
# a high-speed spindle's or a turbo-compressor's, at some 100 000 to 200 000.
SLOWEST_MOTOR_RPM = 1.0
FASTEST_MOTOR_RPM = 1_000_000.0
# An induction motor's rated slip: the largest motors slip some 0.3 %, small and high-slip ones (crane motors, NEMA
# design D) up to some 15 %.  A slip of 1e-12 made Kloss' characteristic a wall the run could not integrate.
SMALLEST_RATED_SLIP = 0.001
LARGEST_RATED_SLIP = 0.5
# A motor's torque on its own shaft (N·m): a constant one's, a linear one's stall torque (typed, or the one its two
# points give) and the torques of its points.  The weakest motors that drive a mechanism, a quartz watch's stepper,
# give some micronewton-metres; the strongest, a grinding mill's gearless ring motor or a ship's slow-speed diesel,
# some 10 MN·m.  A torque of 1e-12 stalled every machine, told as the motor's weakness; one of 1e12 ran it away.
SMALLEST_MOTOR_TORQUE = 1e-6
LARGEST_MOTOR_TORQUE = 1e8
# A motor's rotor inertia (kg·m²): a small induction motor's some 0.001–0.02 (the flywheel starter's 4 kW one
# 0.02), a megawatt one's some tens, the heaviest rotors run as motors, a pumped-storage plant's motor-generators,
# some 1e7.  No least one is asked: 0 leaves the rotor out, and one far lighter is as harmless.  A servo catalogue's
# kg·cm² typed for kg·m² (10 000 times too heavy) is within these: the time the motor takes to run its own rotor up,
# J·ω/M, tells it, and flywheel.rotor_inertia_warning asks of it by that, not refused here.
LARGEST_ROTOR_INERTIA = 1e8


@dataclass(frozen=True)
class MotionSpec:
    """What the scene asks of the machine's motion; :meth:`run` integrates it for a machine."""

    motor: Motor
    motor_off_at: float | None = None
    brake: Brake | None = None
    clutch: Clutch | None = None
    start: Start = REST
    # Whether the scene gave start.angle_deg: a linkage's run then starts at that angle of the crank's own, else at
    # the first position (start.angle is then the 0 of the run's φ, which counts from there).
    start_angle_given: bool = False
    duration: float | None = None
    method: str = "auto"
    rtol: float = DEFAULT_RTOL
    steady_tolerance: float = 1e-4
    # Where the scene gave these (its [dynamics] table's path, and the keys of the start's speed and its driving
    # half's, rev/min's where it gave those), for the refusals to name the key as typed; a spec built in Python
    # names its own fields.
    where: str = ""
    start_keys: tuple[str, str] = ("omega", "driving_omega")
    # The two of a Kloss motor's synchronous_rpm, rated_rpm and rated_slip the scene gave, for the warning of a
    # synchronous speed no motor has to name what was typed and to keep the other as typed.
    kloss_keys: tuple[str, ...] = ()
    # The key the machine's own inertia is given at (a machine known by its load diagrams: "inertia"), or None where
    # the links' masses give it, for a clutch that runs the machine up in no time to name.
    inertia_key: str | None = None
    # Whether the scene wrote the motor's gear_ratio: a warning of a ratio of 1 says it is the default only where
    # it was left out ("gear_ratio = 1.0" typed was told "(the default where it is left out)").
    gear_ratio_given: bool = False

    def _key(self, name: str) -> str:
        """The key path of ``name`` (``"brake.damping"``) as the scene wrote it."""
        return f"{self.where}.{name}" if self.where else name

    def run(self, machine: Machine) -> MachineMotion:
        self._refuse_long_run(machine)
        with self._told_at_its_key():  # simulate refuses a runaway motor and an endless run-down itself
            return simulate(machine, self.motor, duration=self.duration, start=self.start, brake=self.brake,
                            clutch=self.clutch, motor_off_at=self.motor_off_at, method=self.method, rtol=self.rtol,
                            steady_tolerance=self.steady_tolerance)

    def refuse(self, machine: Machine) -> None:
        """Raise :class:`SceneError` (a :class:`ValueError`) at its key for a run of ``machine`` that could not end: a
        motor that outpulls the resistance at every speed from a start that carries the machine past its peaks, a
        run-down that nothing brings to rest, or more turns than a run integrates; found before integrating
        anything."""
        self._refuse_long_run(machine)
        with self._told_at_its_key():
            refuse_runaway(machine, self.motor,
                           self.duration is None and self.brake is None and self.motor_off_at is None, self.start,
                           self.clutch)
            if self.duration is None and self.motor_off_at is not None:
                refuse_endless_run_down(machine, self.brake)

    @contextlib.contextmanager
    def _told_at_its_key(self) -> Iterator[None]:
        """A run that could not end (:class:`EndlessRun`, told at the argument of ``simulate``) as a
        :class:`SceneError` at the scene's key that asked for it (``dynamics.motor.off_at``)."""
        try:
            yield
        except EndlessRun as endless:
            raise SceneError(self._key(endless.scene_key), endless.problem) from None

    def _refuse_long_run(self, machine: Machine) -> None:
        """Raise :class:`SceneError` (a :class:`ValueError`) at the key for a run of more turns than a run
        integrates, or a brake's damping too stiff to integrate."""
        omega_run = running_speed(machine, self.motor, self.start, self.duration)
        self._refuse_stiff_brake(machine, TWO_PI / omega_run)
        self._refuse_weightless_clutched_side(machine, omega_run)
        self._refuse_runaway_past_any_shaft(machine, omega_run)
        if self.duration is not None and self.duration * omega_run > TWO_PI * MOST_TURNS:
            raise SceneError(self._key("duration"), f"{self.duration:g} s is some "
                             f"{self.duration * omega_run / TWO_PI:.3g} turns at the running speed, {omega_run:.4g} "
                             f"rad/s; a run integrates at most {MOST_TURNS} turns")
        # Without a duration a run goes on to its off_at and then runs down: the time to it is bounded as a
        # duration is (with one, an off_at is refused past its end as it is read).
        off_at = self.motor_off_at
        if off_at is not None and off_at * omega_run > TWO_PI * MOST_TURNS:
            raise SceneError(self._key("motor.off_at"), f"{off_at:g} s is some {off_at * omega_run / TWO_PI:.3g} "
                             f"turns at the running speed, {omega_run:.4g} rad/s; a run integrates at most "
                             f"{MOST_TURNS} turns, and runs down once the motor is off: give an off_at of at most "
                             f"{TWO_PI * MOST_TURNS / omega_run:.3g} s", off_at,
                             hint=exponent_slip(off_at * omega_run / TWO_PI, 0.0, MOST_TURNS))
        if self.duration is None and off_at is None:
            self._refuse_after_the_longest_run(MOST_CYCLES * TWO_PI / omega_run)
        # A start far above the running speed (rpm given as rad/s a thousandfold) slows down over more turns
        # than a run integrates, each resolved step by step: the run would hang rather than fail.
        driving = self.start.driving_omega or 0.0
        fastest = max(self.start.omega, driving)
        span = self.duration if self.duration is not None else MOST_CYCLES * TWO_PI / omega_run
        if fastest * span > TWO_PI * MOST_TURNS:
            # Such a start is most often a nameplate's rpm typed as omega: the refusal asks it, as the warning would
            # of a run short enough to integrate.
            key = self.start_keys[1] if driving > self.start.omega else self.start_keys[0]
            in_rpm = not key.endswith("omega")
            rpm_key = self._key(f"start.{key.removesuffix('omega')}rpm")
            typed = (f"; {rpm_question(self._key(f'start.{key}'), fastest, rpm_key)}"
                     if not in_rpm and motor_speed_in_rpm(fastest) else "")
            given = f"{fastest / RPM:.4g} rpm ({fastest:.4g} rad/s)" if in_rpm else f"{fastest:.4g} rad/s"
            raise SceneError(self._key(f"start.{key}"), f"{given} is {fastest / omega_run:.3g} times the running "
                             f"speed, {omega_run:.4g} rad/s; the run could take some {fastest * span / TWO_PI:.3g} "
                             f"turns, and it integrates at most {MOST_TURNS}{typed}")

    def _refuse_runaway_past_any_shaft(self, machine: Machine, omega_run: float) -> None:
        """Raise :class:`SceneError` at a constant motor's ``torque`` that outpulls the resistance at every speed by
        so much that the machine passes :data:`~graphplan.flywheel.FASTEST_MEAN_RPM`, the fastest a machine's shaft
        turns, within the run's duration (``omega_run`` the speed it reaches by then) and within the turns a run
        integrates: that speed is the torque's doing, where the duration was told it asked for too many turns.  A
        machine that would take more turns than that to get there is left to the duration's refusal."""
        fastest = FASTEST_MEAN_RPM * RPM
        if self.duration is None or not omega_run > fastest or not isinstance(self.motor, ConstantTorque):
            return
        reached = runaway_time_to(machine, self.motor, self.start, fastest)
        if reached is None or reached[1] > MOST_TURNS:
            return
        motor = self.motor
        from ..render.numerals import number

        # Written as the warning of a runaway that stays within a machine's speeds writes them.
        shaft, resistance = speeds_up_without_end(machine, motor)
        raise SceneError(self._key("motor.torque"), f"its torque on the shaft, {number(shaft)} N·m, outpulls the mean "
                         f"resistance, {number(resistance)} N·m, at every speed, so far that it runs the machine past "
                         f"{FASTEST_MEAN_RPM:g} rpm, the fastest a machine's shaft turns, {reached[0]:.3g} s into the "
                         f"run, within {self._key('duration')} = {self.duration:g} s, and would take it to some "
                         f"{omega_run / RPM:.3g} rpm by its end: give a torque near the resistance's, or a motor whose "
                         "torque falls with speed (kind = \"linear\" or \"kloss\")", motor.torque)

    def _refuse_after_the_longest_run(self, longest: float) -> None:
        """Raise :class:`SceneError` at a clutch's ``engage_at`` or a brake's ``at`` past ``longest`` s, the time a
        run with no duration and no run-down ends by (:data:`MOST_CYCLES` turns' without a steady state): it never
        acts, and the run said only that the machine was still speeding up, at ω = 0 behind a clutch never engaged."""
        for key, at, never in (("clutch.engage_at", self.clutch.engage_at if self.clutch else None, "engages"),
                               ("brake.at", self.brake.at if self.brake else None, "comes on")):
            if at is not None and at >= longest:
                thing = key.partition(".")[0]
                raise SceneError(self._key(key), f"is past {longest:.4g} s, the {MOST_CYCLES} turns' time at the "
                                 f"running speed that a run with no duration ends by, so the {thing} never {never}: "
                                 f"give a {self._key('duration')} past it, or an earlier {key.partition('.')[2]}",
                                 at, hint=exponent_slip(at, 0.0, longest))

    def _refuse_weightless_clutched_side(self, machine: Machine, omega_run: float) -> None:
        """Raise :class:`SceneError` for a machine behind a clutch whose torque runs it up to ``omega_run`` in less
        than :data:`SHORTEST_CLUTCH_SPIN_UP` of a turn's period: at the machine's own inertia where the scene gives
        it, else at the clutch's torque (a linkage's inertia is its links')."""
        clutch = self.clutch
        if clutch is None:
            return
        period = TWO_PI / omega_run
        inertia = min(machine.je(phi) for phi in np.linspace(0.0, TWO_PI, 64, endpoint=False))
        spin_up = inertia * omega_run / clutch.torque
        if spin_up >= SHORTEST_CLUTCH_SPIN_UP * period:
            return
        shortest = SHORTEST_CLUTCH_SPIN_UP * period
        told = (f"the clutch's {clutch.torque:g} N·m runs the machine's side, {inertia:.3g} kg·m² at its least, up to "
                f"the running speed, {omega_run:.4g} rad/s, in J·ω/Tc = {spin_up:.3g} s, {spin_up / period:.3g} of a "
                f"turn's period, {period:.4g} s: no machine is so light beside its clutch (a friction clutch brings one to "
                "speed over some tenths of a second), and a slip far shorter the run cannot follow")
        if self.inertia_key is not None:
            raise SceneError(self._key(self.inertia_key), f"{told}; give the machine's inertia, at least "
                             f"{shortest * clutch.torque / omega_run:.3g} kg·m² ({SHORTEST_CLUTCH_SPIN_UP:g} of the "
                             f"period to run it up), or a weaker {self._key('clutch')}")
        raise SceneError(self._key("clutch.torque"), f"{told}; give a clutch of at most "
                         f"{inertia * omega_run / shortest:.3g} N·m ({SHORTEST_CLUTCH_SPIN_UP:g} of the period to run "
                         "the machine up), or the links' masses and inertias", clutch.torque)

    def _refuse_stiff_brake(self, machine: Machine, period: float) -> None:
        """Raise :class:`SceneError` at ``brake.damping`` for a brake's damping whose time constant J/c, J the least
        inertia it brakes, is below :data:`SHORTEST_BRAKE_TIME_CONSTANT` of a turn's ``period``."""
        brake = self.brake
        if brake is None or brake.damping == 0:
            return
        # With a clutch the brake may hold the machine's side alone, the driving half slipping.
        rotor = self.motor.reduced_inertia if self.clutch is None else 0.0
        inertia = min(machine.je(phi) for phi in np.linspace(0.0, TWO_PI, 64, endpoint=False)) + rotor
        time_constant = inertia / brake.damping
        if time_constant >= SHORTEST_BRAKE_TIME_CONSTANT * period:
            return
        stiffest = inertia / (SHORTEST_BRAKE_TIME_CONSTANT * period)
        raise SceneError(self._key("brake.damping"), f"{brake.damping:g} N·m·s brakes the shaft's {inertia:.4g} "
                         f"kg·m² with the time constant J/c = {time_constant:.3g} s, {time_constant / period:.3g} of a "
                         f"turn's period at the running speed, {period:.4g} s: it stops the machine dead within a "
                         "sliver of a turn and leaves it creeping at (Md − Mr)/c, which the run cannot follow turn by "
                         f"turn; give a damping of at most {stiffest:.3g} N·m·s (a time constant of "
                         f"{SHORTEST_BRAKE_TIME_CONSTANT:g} of the period), or {self._key('brake.torque')} to hold the "
                         "machine")


def _read_motor(table: Table) -> tuple[Motor, float | None]:
    kind = table.choice("kind", MOTOR_KINDS)
    gear_ratio = table.number("gear_ratio", 1.0, positive=True)
    if not SMALLEST_GEAR_RATIO <= gear_ratio <= LARGEST_GEAR_RATIO:
        raise SceneError(table.where("gear_ratio"), f"must be within {SMALLEST_GEAR_RATIO:g}–{LARGEST_GEAR_RATIO:g}, "
                         "the motor's speed over the driving shaft's, as a machine's gears go (a reducer's some "
                         "2–1000, 14.4 from a motor's 1440 rpm to a press's 100; a step-up gear's down to some "
                         "0.01): the shaft turns at the motor's speed over it, and the rotor's inertia comes to it "
                         "times its square", gear_ratio,
                         hint=exponent_slip(gear_ratio, SMALLEST_GEAR_RATIO, LARGEST_GEAR_RATIO))
    rotor_inertia = table.number("rotor_inertia", 0.0, non_negative=True)
    if not rotor_inertia <= LARGEST_ROTOR_INERTIA:
        raise SceneError(table.where("rotor_inertia"), f"must be at most {LARGEST_ROTOR_INERTIA:g} kg·m², as motors' "
                         "rotors are built (a 4 kW induction motor's some 0.02, a megawatt one's some tens, a "
                         "pumped-storage motor-generator's some 1e7): it comes to the driving shaft times the gear "
                         "ratio's square", rotor_inertia,
                         hint=exponent_slip(rotor_inertia, 0.0, LARGEST_ROTOR_INERTIA))
    drive = {"gear_ratio": gear_ratio, "rotor_inertia": rotor_inertia}
    off_at = table.number("off_at", None, non_negative=True)
    if kind == "constant":
        torque = table.number("torque")
        _refuse_motor_torque(table.where("torque"), torque)
        motor: Motor = ConstantTorque(torque, **drive)
    elif kind == "linear":
        if table.has("points"):
            for key in ("stall_torque", "no_load_rpm"):
                if table.has(key):
                    raise SceneError(table.where(key), "give either points or stall_torque with no_load_rpm, not both")
            pairs = table.items("points", length=2)
            points = []
            for where, item in pairs:
                if not isinstance(item, list) or len(item) != 2:
                    raise SceneError(where, "must be a point [rpm, torque N·m]", item)
                points.append((check_number(item[0], f"{where}[0]"), check_number(item[1], f"{where}[1]")))
            _refuse_points(table.where("points"), points)
            points = [(rpm * RPM, torque) for rpm, torque in points]
            try:
                motor = LinearMotor.through(points[0], points[1], **drive)
            except ValueError as error:
                raise SceneError(table.where("points"), str(error).split(": ", 1)[1]) from None
            # A point at rest is the stall torque's: the line's no-load speed is the motor's speed that is bounded.
            _refuse_motor_speed(table.where("points"), motor.no_load / RPM, table.data["points"],
                                f" (their line gives no torque at {motor.no_load / RPM:.4g} rpm, its no-load speed)")
            _refuse_motor_torque(table.where("points"), motor.stall_torque, table.data["points"],
                                 f" (their line gives {motor.stall_torque:.4g} N·m at rest, its stall torque)")
            # A line of a motor's size through a point no motor has: two slips of the exponent that cancel.
            for (where, item), (rpm, torque) in zip(pairs, points, strict=True):
                _refuse_point(where, rpm / RPM, torque, item)
        else:
            stall_torque = table.number("stall_torque", positive=True)
            _refuse_motor_torque(table.where("stall_torque"), stall_torque)
            no_load_rpm = table.number("no_load_rpm", positive=True)
            _refuse_motor_speed(table.where("no_load_rpm"), no_load_rpm)
            motor = LinearMotor(stall_torque, no_load_rpm * RPM, **drive)
    else:
        power = table.number("power", positive=True)
        if not SMALLEST_MOTOR_POWER <= power <= LARGEST_MOTOR_POWER:
            # 0.75 for a 0.75 kW motor is the likelier slip than a motor of under a watt driving a machine.
            kilowatts = (f"; kilowatts typed for watts? (the scene's power is in W, {power:g} kW is power = "
                         f"{power * 1000:g})" if SMALLEST_MOTOR_POWER <= power * 1000 < 1000 else "")
            raise SceneError(table.where("power"), f"must be within {SMALLEST_MOTOR_POWER:g} W–"
                             f"{LARGEST_MOTOR_POWER / 1e6:g} MW, as induction motors are built (a fan's some watts, a "
                             "rolling mill's some tens of megawatts): Kloss' torques are in proportion to it", power,
                             hint=kilowatts or exponent_slip(power, SMALLEST_MOTOR_POWER, LARGEST_MOTOR_POWER))
        overload = table.number("overload")
        if not overload > 1:
            raise SceneError(table.where("overload"), "must be > 1 (it is Mmax/Mrated)", overload)
        if not overload < LARGEST_OVERLOAD:
            # A catalogue's "Mmax/MN = 220 %" typed as 220; Kloss' formula would take it without a murmur.
            typed = (f"; a percentage typed for the ratio? ({overload:g} % is overload = {overload / 100:g})"
                     if 100 < overload < 100 * LARGEST_OVERLOAD else "")
            raise SceneError(table.where("overload"), f"must be below {LARGEST_OVERLOAD:g}: an induction motor's "
                             "breakdown torque is some 1.6 to 3.5 times its rated one", overload, hint=typed)
        given = [k for k in ("synchronous_rpm", "rated_rpm", "rated_slip") if table.has(k)]
        if len(given) > 2:
            # All three are told at the last: any two fix the third, which may disagree with them.
            raise SceneError(table.where(given[-1]), "give two of synchronous_rpm, rated_rpm, rated_slip, not all "
                             "three (any two fix the third)")
        if len(given) != 2:
            raise SceneError(table.path, "give two of synchronous_rpm, rated_rpm, rated_slip "
                             f"(got {', '.join(given) or 'none'})")
        synchronous = table.number("synchronous_rpm", None, positive=True)
        rated = table.number("rated_rpm", None, positive=True)
        for key, speed in (("synchronous_rpm", synchronous), ("rated_rpm", rated)):
            if speed is not None:
                _refuse_motor_speed(table.where(key), speed)
        slip = table.number("rated_slip", None)
        if slip is not None and not 0 < slip < 1:
            # A catalogue's "sN = 4 %" typed as 4, as δ and ζ are told.
            percentage = f"; {percentage_question(slip, 'rated_slip')}" if 1 <= slip < 100 else ""
            raise SceneError(table.where("rated_slip"), "must be between 0 and 1", slip, hint=percentage)
        if slip is not None:
            _refuse_rated_slip(table.where("rated_slip"), slip, slip)
        if slip is None:
            if not rated < synchronous:
                raise SceneError(table.where("rated_rpm"), f"must be below synchronous_rpm ({synchronous!r})", rated)
            slip = 1.0 - rated / synchronous
            # Two speeds typed a hair apart (1499.9999 under 1500) give a slip no motor has, told at the rated one.
            _refuse_rated_slip(table.where("rated_rpm"), slip, rated, f" (with synchronous_rpm = {synchronous:g}, "
                               f"the slip 1 − rated_rpm/synchronous_rpm is {slip:.3g})")
        elif synchronous is None:
            synchronous = rated / (1.0 - slip)
        motor = KlossMotor(power, synchronous * RPM, slip, overload, **drive)
    table.done(elsewhere=misplaced_keys(table.path, _owner(table)))
    return motor, off_at


def _refuse_motor_speed(where: str, rpm: float, typed: object = None, derived: str = "") -> None:
    """Raise :class:`SceneError` at ``where`` for a motor's speed (rev/min) outside the speeds motors turn at: the
    value typed there, or one ``typed`` there gives, as ``derived`` says."""
    if SLOWEST_MOTOR_RPM <= rpm <= FASTEST_MOTOR_RPM:
        return
    bounds = f"{SLOWEST_MOTOR_RPM:g}–{FASTEST_MOTOR_RPM:.0f} rpm"
    raise SceneError(where, (f"gives a speed outside {bounds}" if derived else f"must be within {bounds}") +
                     ", as motors turn (a low-speed hydraulic one some tens, a 50 Hz induction one up to 3000, a "
                     f"high-speed spindle some 100 000){derived}", rpm if typed is None else typed,
                     hint=exponent_slip(rpm, SLOWEST_MOTOR_RPM, FASTEST_MOTOR_RPM))


def _refuse_motor_torque(where: str, torque: float, typed: object = None, derived: str = "") -> None:
    """Raise :class:`SceneError` at ``where`` for a motor's torque (N·m, on its own shaft) outside the torques motors
    give: the value typed there, or one ``typed`` there gives, as ``derived`` says."""
    if SMALLEST_MOTOR_TORQUE <= torque <= LARGEST_MOTOR_TORQUE:
        return
    if not torque > 0:
        # Only a constant motor's torque is typed with any sign: nought or less drives nothing.
        raise SceneError(where, "must be > 0, the torque the motor drives the machine with (a run-down with the motor "
                         "off is off_at's)", torque if typed is None else typed)
    bounds = f"{SMALLEST_MOTOR_TORQUE:g}–{LARGEST_MOTOR_TORQUE:g} N·m"
    # A drawing's or a small motor's catalogue's N·mm is a thousand times the N·m; within the bounds it runs (and
    # the machine is told of it, too strong a motor running away), beyond them it is asked here.
    newton_millimetres = (f"; N·mm typed for N·m? (the scene's torques are in N·m: {torque:g} N·mm is "
                          f"{torque / 1000:g} N·m)" if LARGEST_MOTOR_TORQUE < torque <= 1000 * LARGEST_MOTOR_TORQUE
                          else "")
    raise SceneError(where, (f"gives a torque outside {bounds}" if derived else f"must be within {bounds}") +
                     ", as motors drive machines (a watch's stepper some micronewton-metres, a 4 kW induction motor "
                     f"some 26 N·m, a grinding mill's ring motor some 10 MN·m){derived}",
                     torque if typed is None else typed,
                     hint=newton_millimetres or exponent_slip(torque, SMALLEST_MOTOR_TORQUE, LARGEST_MOTOR_TORQUE))


def _refuse_point(where: str, rpm: float, torque: float, typed: object) -> None:
    """Raise :class:`SceneError` at ``where`` (``points[k]``) for a linear motor's point ``[rpm, N·m]`` beyond the
    speeds motors turn at or the torques they give, either way (a point past the no-load speed has a negative
    torque)."""
    if abs(rpm) <= FASTEST_MOTOR_RPM and abs(torque) <= LARGEST_MOTOR_TORQUE:
        return
    raise SceneError(where, f"must be within ±{FASTEST_MOTOR_RPM:.0f} rpm and ±{LARGEST_MOTOR_TORQUE:g} N·m, the "
                     "speeds motors turn at and the torques they give", typed,
                     hint=("; a slip of the exponent?" if abs(rpm) > 1000 * FASTEST_MOTOR_RPM
                           or abs(torque) > 1000 * LARGEST_MOTOR_TORQUE else ""))


def _refuse_rated_slip(where: str, slip: float, typed: float, derived: str = "") -> None:
    """Raise :class:`SceneError` at ``where`` (``rated_slip``, or ``rated_rpm`` where the slip follows from the two
    speeds, said in ``derived``) for a rated slip outside the slips of induction motors."""
    if SMALLEST_RATED_SLIP <= slip <= LARGEST_RATED_SLIP:
        return
    bounds = f"{SMALLEST_RATED_SLIP:g}–{LARGEST_RATED_SLIP:g}"
    raise SceneError(where, (f"gives a rated slip outside {bounds}" if derived else f"must be within {bounds}") +
                     ", as induction motors slip (a large one some 0.003, a small or high-slip one up to some 0.15)"
                     f"{derived}: Kloss' characteristic is drawn through it", typed)


def _owner(table: Table) -> str:
    """The path of the ``[dynamics]`` table a motion's table (``dynamics.motor``) is nested in."""
    return table.path.rpartition(".")[0]


def _refuse_points(where: str, points: list[tuple[float, float]]) -> None:
    """Raise :class:`SceneError` at ``where`` for a linear motor's two points ``[rpm, N·m]`` that give no motor,
    told in the units they were typed in (the motor's class would tell rad/s)."""
    (n1, m1), (n2, m2) = points
    typed = f"{m1:g} N·m at {n1:g} rpm, {m2:g} N·m at {n2:g} rpm"
    if n1 == n2:
        raise SceneError(where, f"the two points need different speeds (got {n1:g} rpm twice)")
    slope = (m2 - m1) / (n2 - n1)
    if not slope < 0:
        raise SceneError(where, f"the torque must fall as the speed rises (got {typed})")
    if not m1 - slope * n1 > 0:
        raise SceneError(where, f"the line through them gives the motor no torque at rest, {m1 - slope * n1:.4g} N·m "
                         f"at 0 rpm: a motor's torque is > 0 from rest up to its no-load speed (got {typed})")


def _read_brake(table: Table) -> Brake:
    torque = table.number("torque", 0.0, non_negative=True)
    damping = table.number("damping", 0.0, non_negative=True)
    # A brake switched on before the run starts would be on from its start: a negative time is a slip.
    at = table.number("at", 0.0, non_negative=True)
    if torque == 0 and damping == 0:
        raise SceneError(table.path, "needs torque > 0 or damping > 0")
    table.done(elsewhere=misplaced_keys(table.path, _owner(table)))
    return Brake(torque=torque, damping=damping, at=at)


def _read_clutch(table: Table) -> Clutch:
    # A clutch engaged before the run starts would be engaged from its start: a negative time is a slip, as a brake's.
    clutch = Clutch(torque=table.number("torque", positive=True),
                    engage_at=table.number("engage_at", 0.0, non_negative=True),
                    inertia=table.number("inertia", 0.0, non_negative=True))
    table.done(elsewhere=misplaced_keys(table.path, _owner(table)))
    return clutch


# What a negative start speed is told: the run takes its size, and it turns the way the driver does.
_SIZE_ONLY = ": it is the speed's size, and its sense is the driver's (the sign of driver.omega or driver.rpm)"


def _read_start(value: Any, where: str, clutch: Clutch | None) -> Start:
    if isinstance(value, str):
        if value != "rest":
            raise SceneError(where, "must be \"rest\" or a table {omega or rpm, angle_deg, driving_omega or "
                             "driving_rpm}", value)
        return REST
    table = Table(value, where)
    omega = table.speed(0.0, non_negative=True, sense=_SIZE_ONLY)
    _refuse_start_speed(table, "omega", "rpm", omega)
    angle = math.radians(table.number("angle_deg", 0.0))
    driving = table.speed(None, omega_key="driving_omega", rpm_key="driving_rpm", non_negative=True, sense=_SIZE_ONLY)
    _refuse_start_speed(table, "driving_omega", "driving_rpm", driving)
    if driving is not None and clutch is None:
        key = "driving_omega" if table.has("driving_omega") else "driving_rpm"
        raise SceneError(table.where(key), "only with a clutch")
    table.done(elsewhere=misplaced_keys(table.path, _owner(table)))
    return Start(omega=omega, angle=angle, driving_omega=driving)


def _refuse_start_speed(table: Table, omega_key: str, rpm_key: str, omega: float | None) -> None:
    """Raise :class:`SceneError` at the start's ``omega_key`` or ``rpm_key``, as typed, for a speed (``omega``, rad/s
    as read) above :data:`~graphplan.flywheel.FASTEST_MEAN_RPM`, the fastest a shaft with a flywheel turns: the
    driving shaft starts at no more than it runs (a start far above the machine's own mean speed is refused where
    that is known, :func:`~graphplan.flywheel.read_dynamics`)."""
    if omega is None or omega / RPM <= FASTEST_MEAN_RPM:
        return
    in_rpm = table.has(rpm_key)
    key = rpm_key if in_rpm else omega_key
    bounds = f"{FASTEST_MEAN_RPM:g} rpm" if in_rpm else f"{FASTEST_MEAN_RPM * RPM:.5g} rad/s ({FASTEST_MEAN_RPM:g} rpm)"
    raise SceneError(table.where(key), f"must be at most {bounds}, as the driving shaft of a machine turns (a press's "
                     "some 10–100 rpm, an engine's up to some 10 000): the run starts the shaft at this speed",
                     table.data[key], hint=exponent_slip(omega / RPM, 0.0, FASTEST_MEAN_RPM))


def read_motion(table_or_dict: Table | Mapping[str, Any], path: str = "dynamics") -> MotionSpec:
    """The motion's keys of the scene's ``[dynamics]`` table.

    ``motor`` (required), ``brake``, ``clutch``, ``start``, ``duration``, ``method``, ``rtol``,
    ``steady_tolerance``.  A :class:`~graphplan.reader.Table` is read for these keys only and its
    owner calls ``done()``; a plain mapping is read whole, so any other key in it is unknown.
    """
    owned = isinstance(table_or_dict, Table)
    table = table_or_dict if owned else Table(dict(table_or_dict) if isinstance(table_or_dict, Mapping)
                                              else table_or_dict, path)
    if not table.has("motor"):
        # A brake or a clutch alone was told only that the motor is missing, not what asked for it.
        asking = next((key for key in ("brake", "clutch", "start", "duration") if table.has(key)), None)
        if asking is not None:
            raise SceneError(table.where("motor"), f"is required with {table.where(asking)}: the equation of motion "
                             "is run with a motor (a run-down to rest: a motor with off_at, the time it is switched "
                             "off)")
    motor_table = table.table("motor")
    motor, off_at = _read_motor(motor_table)
    brake_table = table.table("brake", None)
    clutch_table = table.table("clutch", None)
    brake = _read_brake(brake_table) if brake_table is not None else None
    clutch = _read_clutch(clutch_table) if clutch_table is not None else None
    if clutch is not None and clutch.inertia + motor.reduced_inertia <= 0:
        raise SceneError(clutch_table.where("inertia"), "the clutch's driving half needs an inertia: "
                         "give clutch.inertia or motor.rotor_inertia")
    raw_start = table.raw("start", "rest")
    given = raw_start if isinstance(raw_start, Mapping) else {}
    start_keys = ("rpm" if "rpm" in given else "omega", "driving_rpm" if "driving_rpm" in given else "driving_omega")
    start = _read_start(raw_start, table.where("start"), clutch)
    if off_at == 0 and start.omega == 0 and not start.driving_omega:
        # Nothing would ever move: the run would integrate a machine at rest to the longest run it allows.
        raise SceneError(motor_table.where("off_at"), "switches the motor off as a run from rest begins, so the "
                         "machine never turns: give off_at > 0, or a start with a speed to run down from", off_at)
    duration = table.number("duration", None, positive=True)
    if off_at is not None and duration is not None and off_at >= duration:
        # The run ends before the motor is switched off: the run-down asked for would never be seen.
        raise SceneError(motor_table.where("off_at"), f"is at or past the run's end, {table.where('duration')} = "
                         f"{duration:g} s, so the motor is never switched off: give an off_at below the duration to "
                         "see the run-down, or leave it out", off_at)
    for owner, key, at, never in ((clutch_table, "engage_at", clutch.engage_at if clutch else None, "engages"),
                                  (brake_table, "at", brake.at if brake else None, "comes on")):
        if at is not None and duration is not None and at >= duration:
            # The run ends before the clutch or brake acts: it would be described as acting, and never be seen to.
            thing = owner.path.rpartition(".")[2]
            raise SceneError(owner.where(key), f"is at or past the run's end, {table.where('duration')} = "
                             f"{duration:g} s, so the {thing} never {never}: give {key} below the duration, or leave "
                             f"the {thing} out", at)
    method = table.choice("method", METHODS, "auto")
    rtol = table.number("rtol", DEFAULT_RTOL, positive=True)
    if not rtol < 1:
        raise SceneError(table.where("rtol"), "must be < 1", rtol)
    if rtol < SMALLEST_RTOL:
        raise SceneError(table.where("rtol"), f"must be at least {SMALLEST_RTOL:.3g}: 100 machine epsilons, the "
                         "least the solvers take", rtol)
    steady_tolerance = table.number("steady_tolerance", 1e-4, positive=True)
    if not steady_tolerance <= LARGEST_STEADY_TOLERANCE:
        raise SceneError(table.where("steady_tolerance"), f"must be at most {LARGEST_STEADY_TOLERANCE:g}: how near "
                         "successive turns' ωm (relative) and δ must have come for the run to be steady, and a looser "
                         "one takes turns of the start-up for the steady state and reports their ωm and δ as the "
                         "machine's", steady_tolerance)
    if not owned:
        table.done(elsewhere=misplaced_keys(table.path, table.path))
    return MotionSpec(motor=motor, motor_off_at=off_at, brake=brake, clutch=clutch, start=start,
                      start_angle_given=isinstance(raw_start, Mapping) and "angle_deg" in raw_start, duration=duration,
                      method=method, rtol=rtol, steady_tolerance=steady_tolerance, where=table.path,
                      start_keys=start_keys,
                      kloss_keys=tuple(key for key in ("synchronous_rpm", "rated_rpm", "rated_slip")
                                       if motor_table.has(key)),
                      gear_ratio_given=motor_table.has("gear_ratio"))
