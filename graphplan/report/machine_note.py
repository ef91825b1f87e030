"""The note's sections on the machine: its dynamics (the equivalent model, the flywheel, the motion in time), balancing
the rotor and the vibration its unbalance causes.

Each is worked out as a student's note works it: the equation, the numbers put into it, the result with
its unit.  The balancing goes by the polygon of each correction plane (a long rotor's mass-radius
products first carried to its two planes, as a load to two supports); the vibration from the natural
frequency to the amplitude, the force the mounts pass to the base and the mounts that would isolate it.
The sections are written by the note's own writer, whose numbering, tables and language they share.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from typing import TYPE_CHECKING, Protocol

import numpy as np

from ..loads import external_names
from ..locale import Count
from ..render.numerals import angle_in_turn, power_of_ten, steady_delta, worked_out
from ..units import RPM
from .markdown import literal

# The run's dynamics are worked out where the note is written from.  The rotor's and the vibration's modules (and
# the plots') are imported by the sections that write them: every note imports this module, and a linkage's has
# neither, whose cold run they cost 35 ms.
if TYPE_CHECKING:
    from ..machine_dynamics import MachineDynamics
    from ..rotor_balancing import BalancingResult
    from ..rotor_lengths import LengthsInMillimetres
    from ..scene import Scene
    from ..vibration import MountsSag, NearResonance, Response, Shaft, VibrationSpec


class Writer(Protocol):
    """What a section needs of the note it is written into."""

    text: Mapping[str, str]
    mark: str
    scene: Scene
    found: dict[str, object]

    def t(self, key: str, **values: object) -> str: ...
    def n(self, value: float, digits: int = 5) -> str: ...
    def heading(self, level: int, title: str, number: object = None) -> None: ...
    def para(self, *lines: str) -> None: ...
    def figure(self, file: str, caption: str, lead: str = "figure_lead") -> None: ...
    def table(self, caption: str | None, header: list[str], rows: list[list[str]], align: str | None = None,
              lead: str | None = "table_lead") -> None: ...
    @property
    def next_table(self) -> int: ...


def dynamics_section(note: Writer, section: int, dynamics: MachineDynamics) -> None:
    """The equivalent model (by the plans beside the exact one), its energy, the flywheel and the motion in time."""
    model, flywheel = dynamics.model, dynamics.flywheel
    turning = model.turning
    # The texts of a run once over a swing or a travel, not over a cycle, say so.
    run = "" if model.cyclic else "_swing" if turning else "_travel"
    note.heading(2, note.t("note_dynamics"), section)
    from ..flywheel import crank_omega, rpm_typed_speeds, speed_unit_slip

    # The file outlives the console: a speed typed off a motor's nameplate spoils all worked out from it.
    for role, _, omega in rpm_typed_speeds(note.scene.dynamics):
        note.para(note.t("note_dyn_caution_speed_in_rpm", speed=note.text[f"note_dyn_speed_{role}"],
                         omega=note.n(omega), rpm=note.n(omega / RPM), meant=note.n(omega * RPM)))
    slip = speed_unit_slip(note.scene.dynamics, crank_omega(note.scene.driver))
    if slip is not None:  # so is the crank's own speed typed in the other unit, and the flywheel sized from it
        # In words, not the scene's keys: the note's reader has the note, not the scene.
        note.para(note.t("note_dyn_caution_rpm_as_rad" if slip.key == "rpm" else "note_dyn_caution_rad_as_rpm",
                         typed=note.n(slip.typed), omega=note.n(slip.crank_omega), rpm=note.n(slip.crank_rpm),
                         sized=note.n(slip.sized), ratio=note.n(slip.times_off, 3),
                         square=f"{slip.times_off ** 2:.0f}"))
    odd = dynamics.synchronous
    if odd is not None:  # the console's line, for the motor's whole characteristic below is reckoned from it
        note.para(note.t("note_dyn_caution_synchronous_rated" if odd.rated_typed else "note_dyn_caution_synchronous",
                         typed=note.n(odd.typed), nearest=note.n(odd.nearest)))
    if model.link == 0:  # known by its load diagrams alone, no linkage reduced to a link
        # The points the scene gives, not the samples the model is worked on (362 for a diagram of 4).
        given = sum(len(diagram.angles_deg) for diagram in note.scene.dynamics.diagrams)
        key = "note_dyn_model_diagrams_no_inertia" if model.inertia_is_nought else "note_dyn_model_diagrams"
        note.para(note.t(key, count=Count(given), inertia=note.n(model.mean_inertia)))
        _powers_to_moments(note, note.scene.dynamics)
    else:
        # The scene's steps: the samples are one more over a travel, and more again where a load switches on.
        note.para(note.t("note_dyn_model" + run if turning else "note_dyn_model_slider", link=model.link,
                         count=Count(note.scene.dynamics.count)))
        if note.scene.friction:   # the force analysis takes it in, and a reader would think these numbers do too
            note.para(note.text["note_dyn_without_friction"])
    if model.plans:
        _reductions(note, model)
    if model.moved:  # a load the scene gives as driving that takes work: counted with the resistances
        names = dict(zip((load.where for load in note.scene.loads), external_names(note.scene.loads), strict=True))
        springs = {load.where for load in note.scene.loads if load.spring}
        for moved in model.moved:  # a force given over several strokes is their sum
            # A spring was given as no driving load: it goes with the weights as the machine's own.
            told = "note_dyn_spring" if set(moved.loads) <= springs else "note_dyn_reclassified"
            note.para(note.t(f"{told}{run}", name=" + ".join(names[where] for where in moved.loads),
                             work=note.n(moved.work)))
    if model.constant in ("driving", "resisting"):
        side = model.driving if model.constant == "driving" else -model.resisting
        # Over the run, not over the samples: a resisting side keeps the weights, whose moment the two samples of
        # every switch and corner would weigh twice (40.752 N·m for an engine's 256 J/2π = 40.744).
        note.para(note.t(f"note_dyn_constant_{model.constant}{run}", value=note.n(model.mean_over_run(side))))
    energy = model.energy
    # Worked out as the flywheel's ΔWmax is, on the drawing and below: 441.20 J, not 441.2.
    ends = (float(energy.min()), float(energy.max()), float(np.ptp(energy)))
    low, high, value = (worked_out(end).replace(".", note.mark) for end in ends)
    note.para(note.t(f"note_dyn_energy{run}", low=low, high=high, value=value))
    if flywheel is not None:
        _flywheel(note, flywheel, model)
    note.figure("dynamics.svg", note.text["dyn_title" if flywheel is not None else "dyn_title_model"])
    if dynamics.motion is not None:
        _motion(note, dynamics, flywheel)
        note.figure("motion.svg", note.t("motion_title", title=literal(note.scene.title)), lead="plot_lead")


def _reductions(note: Writer, model) -> None:
    text = note.text
    # A plan gives the loads' and the weights' reduced load, never the constant side: that is Mr where the driving
    # side is taken constant, Me where neither is, and where the resisting side is, the driving loads' and the
    # weights' (an engine's gas force), which no curve of the drawing is and a column headed Me passed for.
    kind = "" if model.turning else "force_"
    loaded = text[f"note_dyn_plans_{kind}symbol_{model.constant}"] if model.constant != "none" else \
        text["note_dyn_moment_symbol" if model.turning else "note_dyn_force_symbol"]
    # The symbols the dynamics sheet draws, so that the table and the drawing name a quantity alike (Jп, Mс).
    inertia, moment = ((text["note_dyn_inertia_symbol"], text["kilogram_metre2"]), (loaded, text["newton_metre"])) \
        if model.turning else ((text["note_dyn_mass_symbol"], text["kilogram"]), (loaded, text["newton"]))
    where = text["dyn_angle_axis"] if model.turning else text["dyn_travel_axis"]
    by_plan, analytic = (text["bracketed"].format(words=text[key]) for key in ("column_by_plan", "column_analytic"))
    header = [text["note_dyn_position"], where,
              f"{inertia[0]}, {inertia[1]}{by_plan}", f"{inertia[0]}{analytic}", text["note_dyn_error"],
              f"{moment[0]}, {moment[1]}{by_plan}", f"{moment[0]}{analytic}", text["note_dyn_error"]]
    rows = []
    for plan in model.plans:
        at = math.degrees(plan.driver) % 360.0 if model.turning else plan.driver
        rows.append([str(plan.number), note.n(at, 4), note.n(plan.inertia), note.n(plan.inertia_exact),
                     _percent(note, plan.inertia_error_percent), note.n(plan.moment), note.n(plan.moment_exact),
                     _percent(note, plan.moment_error_percent)])
    # A slider's are a mass and a force, named as its drawing names them (Fr, not the crank's Mr).
    note.table(text["note_dyn_table" if model.turning else "note_dyn_table_slider"], header, rows, align="rrrrrrrr")
    note.para(note.t(f"note_dyn_plans_load_{kind}{model.constant}", symbol=loaded))


def _percent(note: Writer, value: float) -> str:
    """An error in percent to a thousandth, as the error tables print it (no −0)."""
    if not math.isfinite(value):
        return note.n(value)
    return f"{round(value, 3) or 0.0:.3f}".replace("-", "−").replace(".", note.mark)


def _flywheel(note: Writer, flywheel, model) -> None:
    from ..flywheel import LARGEST_USUAL_DELTA, unusual_speed_swing
    from ..render.dynamics import flywheel_numbers

    delta = flywheel.delta
    if (swing := unusual_speed_swing(delta)) is not None:
        note.para(note.t("note_dyn_caution_delta", delta=note.n(delta), usual=note.n(LARGEST_USUAL_DELTA),
                         ratio=note.n(swing, 3), fraction=note.n(delta / 100)))
    # The numbers the dynamics drawing writes beside the same quantities, to the same digits.
    numbers = {name: None if value is None else value.replace(".", note.mark)
               for name, value in flywheel_numbers(model, flywheel)._asdict().items()}
    speeds = {"high": numbers["omega_max"], "low": numbers["omega_min"], "high_angle": numbers["angle_max"],
              "low_angle": numbers["angle_min"]}
    note.found["flywheel"] = {"needed": flywheel.inertia > 0, "delta": numbers["delta"], "inertia": numbers["required"]}
    if flywheel.inertia <= 0:
        note.para(note.t("note_dyn_no_flywheel", delta=numbers["delta"], required=numbers["required"],
                         reached=note.n(flywheel.reached, 4), **speeds))
        return
    given = {"delta": numbers["delta"], "omega": numbers["omega_mean"], "rpm": numbers["rpm"],
             "work": numbers["delta_w_max"], "mean": note.n(model.mean_inertia), "exact": numbers["required"]}
    if model.inertia_is_constant:
        key = "note_dyn_flywheel_no_inertia" if model.inertia_is_nought else "note_dyn_flywheel_constant"
        note.para(note.t(key, **given))
    else:
        note.para(note.t("note_dyn_flywheel", approximate=numbers["approximate"], mertsalov=numbers["mertsalov"],
                         **given))
        if flywheel.approximate < 0:   # the constant-Je estimate spares what the varying Je does not
            note.para(note.t("note_dyn_approximate_negative", low=note.n(float(np.min(model.inertia))),
                             high=note.n(float(np.max(model.inertia))), exact=numbers["required"]))
        else:
            # Three values and no word of which to mount: a student took the approximate one, 24 % short.
            off = abs(flywheel.required - flywheel.approximate) / flywheel.required * 100.0
            note.para(note.t("note_dyn_flywheel_taken", exact=numbers["required"], off=note.n(off, 2)))
    note.para(note.t("note_dyn_speeds_shaft" if model.link == 0 else "note_dyn_speeds", **speeds))
    if numbers["moved"] is not None:
        note.para(note.t("note_dyn_moved", rpm=numbers["shaft_rpm"], value=numbers["moved"]))


def _method_reason(note: Writer, dynamics) -> str:
    """Why the integrator was taken, in the note's language (the run's own reason is in English)."""
    from ..machine_motion import STIFFNESS_THRESHOLD

    number = note.n(dynamics.motion.stiffness, 3)
    if dynamics.spec.motion.method != "auto":
        return note.t("note_dyn_reason_asked", number=number)
    return note.t("note_dyn_reason_stiff" if dynamics.motion.stiff else "note_dyn_reason_not_stiff", number=number,
                  threshold=note.n(STIFFNESS_THRESHOLD))


def _motion(note: Writer, dynamics, flywheel) -> None:
    motion, spec = dynamics.motion, dynamics.spec.motion
    _motor(note, spec.motor)
    _equation(note, dynamics)
    if spec.clutch is not None:
        _clutch(note, dynamics)
    brake = spec.brake
    if brake is not None:
        # With no damping the brake's moment is its torque alone: "+ 0·ω" would name a term that is not there.
        key = "note_dyn_brake" if brake.damping else "note_dyn_brake_constant"
        note.para(note.t(key, at=note.n(brake.at, 4), torque=note.n(brake.torque),
                         damping=note.n(brake.damping),
                         equation=_shaft_equation(note, dynamics, braking=f"{key}_symbol")))
    steady = motion.steady
    # Stopped with the motor on is a stall; stopped after it was switched off, a run-down.
    run_down = motion.stalled_at is None and motion.stopped_at is not None
    if steady is None:
        if run_down:
            _run_down(note, dynamics)
        elif dynamics.spec.motion.motor_off_at is not None and motion.stalled_at is None:
            note.para(note.t("note_dyn_not_stopped", off=note.n(dynamics.spec.motion.motor_off_at, 4),
                             time=note.n(float(motion.t[-1]), 4), speed=note.n(float(motion.omega[-1]))))
        elif motion.stalled_at is None:
            note.para(note.text["note_dyn_no_steady"])
            runaway = dynamics.runaway()
            if runaway is not None:
                note.para(note.t("note_dyn_runaway", torque=note.n(runaway[0]), resisting=note.n(runaway[1])))
        else:
            _stall(note, dynamics)
        return
    cycle = steady.cycle
    # Worked out, each to its digits: ωmax = 6.3770 beside ωmin = 6.2289, δ = 0.02350 (the simulation's four), where
    # 6.377 and 0.0235 read as known to a digit less.
    speeds = {name: worked_out(speed).replace(".", note.mark) for name, speed in
              (("mean", steady.mean_speed), ("high", cycle.max_speed), ("low", cycle.min_speed),
               ("middle", cycle.middle_speed))}
    reached = steady_delta(cycle.delta).replace(".", note.mark)
    note.para(note.t("note_dyn_steady", start_up=note.n(motion.start_up_time(5.0), 4), after=note.n(steady.reached_at, 4),
                     delta=reached, **speeds))
    if flywheel is not None and flywheel.inertia > 0:
        note.para(note.t("note_dyn_steady_sized", sized=note.n(flywheel.delta), delta=reached))
        _off_design(note, dynamics, speeds["mean"], reached)
    if run_down:
        _run_down(note, dynamics)


def _powers_to_moments(note: Writer, spec) -> None:
    """How a diagram given in watts became the moments the model is worked on, M = P/ωm, shown on its peak: the note
    said only that the moments were given as diagrams."""
    for diagram in spec.diagrams:
        if diagram.quantity != "power":
            continue
        peak = max(diagram.values, key=abs)
        note.para(note.t(f"note_dyn_power_to_moment_{diagram.side}", omega=note.n(spec.omega), power=note.n(peak),
                         moment=note.n(peak / spec.omega)))


def _off_design(note: Writer, dynamics, settled: str, reached: str) -> None:
    """The command line's off-design line, where the motor settles the machine away from the speed its flywheel was
    sized at: the file outlives the console.  ``settled`` and ``reached`` are ωm and δ as the steady paragraph wrote
    them."""
    from ..render.dynamics import flywheel_numbers

    off = dynamics.off_design()
    if off is None:
        return
    flywheel, gear, slip = dynamics.flywheel, dynamics.gear, dynamics.speed_slip
    given = {"settled": settled, "percent": f"{abs(off[0] / off[1] - 1.0) * 100:.0f}", "delta": reached,
             "sized": flywheel_numbers(dynamics.model, flywheel).omega_mean.replace(".", note.mark),
             "asked": note.n(flywheel.delta)}
    # As the console: a mistyped speed first; else a gear far off the machine's speed, with the ratio that fits.
    if slip is not None:
        note.para(note.t("note_dyn_off_design_speed", **given))
    elif gear is not None:
        note.para(note.t("note_dyn_off_design_gear", **given, ratio=note.n(gear.gear_ratio),
                         at_shaft=note.n(gear.at_shaft / RPM, 4), motor=note.n(gear.speed / RPM),
                         mean=note.n(gear.mean / RPM), fitting=note.n(gear.fitting_ratio, 3)))
    else:
        note.para(note.t("note_dyn_off_design", **given))


def _motor(note: Writer, motor) -> None:
    """The motor's characteristic with its numbers, and the driving moment it gives the driving shaft through its
    gear, ``Md(ω) = u·M(u·ω)``: the scene gives the motor on its own shaft, the equation of motion takes it on the
    crank's.  Each operand is written to the digits that make its equations come out as written
    (:func:`shown_operand`)."""
    from ..machine_motion import ConstantTorque, KlossMotor

    u = motor.gear_ratio
    # A motor on the driving shaft itself has no gear to name, and u = 1 reduces nothing.
    gear = note.t("note_dyn_gear", ratio=note.n(u)) if u != 1 else note.text["note_dyn_gear_direct"]
    ratio = read_number(note, note.n(u))
    if isinstance(motor, ConstantTorque):
        driving = note.n(u * motor.torque)
        note.para(note.t("note_dyn_motor_constant", gear=gear, ratio=note.n(u), driving=driving,
                         torque=shown_operand(note, motor.torque, [(lambda m: ratio * m, driving)])))
    elif isinstance(motor, KlossMotor):
        _kloss(note, motor, gear)
    else:  # linear, by its stall torque and no-load speed or through two points, which fix the same line
        stall_shaft, no_load_shaft = note.n(u * motor.stall_torque), note.n(motor.no_load / u)
        note.para(note.t("note_dyn_motor_linear", gear=gear, ratio=note.n(u), rpm=note.n(motor.no_load / RPM),
                         stall=shown_operand(note, motor.stall_torque, [(lambda m: ratio * m, stall_shaft)]),
                         no_load=shown_operand(note, motor.no_load, [(lambda w: w / ratio, no_load_shaft)]),
                         stall_shaft=stall_shaft, no_load_shaft=no_load_shaft))


def _kloss(note: Writer, motor, gear: str) -> None:
    """An induction motor by Kloss' formula: from its rated point and overload capacity to its breakdown torque,
    critical slip and starting torque, on its own shaft and on the driving shaft."""
    u, lam = motor.gear_ratio, motor.overload
    sk = motor.critical_slip
    starting = 2.0 * motor.max_torque / (1.0 / sk + sk)
    ratio, overload = read_number(note, note.n(u)), read_number(note, note.n(lam))
    written = {"rated_shaft": note.n(u * motor.rated_torque), "rated_speed_shaft": note.n(motor.rated_speed / u),
               "max_shaft": note.n(u * motor.max_torque), "starting_shaft": note.n(u * starting),
               "starting": note.n(starting)}
    # Each operand is settled after the equations it is an operand of have theirs: sk and Mmax give the starting
    # torque, sN gives sk, MN gives Mmax, ωN gives MN, ωs and sN give ωN.
    written["critical"] = shown_operand(note, sk, [(lambda s: 2.0 * motor.max_torque / (1.0 / s + s),
                                                    written["starting"])])
    critical = read_number(note, written["critical"])
    written["max"] = shown_operand(note, motor.max_torque, [
        (lambda m: 2.0 * m / (1.0 / critical + critical), written["starting"]), (lambda m: ratio * m, written["max_shaft"])])
    written["slip"] = shown_operand(note, motor.rated_slip, [
        (lambda s: s * (overload + math.sqrt(overload ** 2 - 1.0)), written["critical"])])
    written["rated"] = shown_operand(note, motor.rated_torque, [
        (lambda m: overload * m, written["max"]), (lambda m: ratio * m, written["rated_shaft"])])
    power = read_number(note, note.n(motor.power))
    written["rated_speed"] = shown_operand(note, motor.rated_speed, [
        (lambda w: power / w, written["rated"]), (lambda w: w / ratio, written["rated_speed_shaft"])])
    slip = read_number(note, written["slip"])
    written["synchronous"] = shown_operand(note, motor.synchronous_speed, [
        (lambda w: w * (1.0 - slip), written["rated_speed"])])
    note.para(note.t("note_dyn_motor_kloss", gear=gear, ratio=note.n(u), power=note.n(motor.power),
                     overload=note.n(lam), synchronous_rpm=note.n(motor.synchronous_speed / RPM),
                     rated_rpm=note.n(motor.rated_speed / RPM), **written))


def _shaft_equation(note: Writer, dynamics, braking: str | None = None, slipping: bool = False) -> str:
    """The equation of motion of the driving shaft as the run integrates it: the machine's Je(φ) with the flywheel,
    and the motor's rotor and the clutch's driving half where they turn with it (not while a clutch slips: the
    driving half then has its own equation, and the machine is driven by the clutch's torque); ``braking`` is the
    key of the brake's term, where one acts.  A Je that does not vary has no Je′ term and is no function of φ: the
    equation is then J·dω/dt = Md − Mr, as the textbooks write it for a constant inertia."""
    text = note.text
    constant = dynamics.model.inertia_is_constant
    inertia = [] if _own_inertia_left_out(dynamics) else [text["note_dyn_inertia_symbol"] + ("" if constant else "(φ)")]
    if dynamics.flywheel_inertia > 0:
        inertia.append(text["note_dyn_flywheel_symbol"])
    if not slipping:
        inertia += _driving_half(note, dynamics)
    return note.t("note_dyn_equation_constant" if constant else "note_dyn_equation", inertia=_sum(inertia),
                  driving=text["note_dyn_clutch_torque_symbol" if slipping else "note_dyn_driving_symbol"],
                  braking=text[braking] if braking else "")


def _own_inertia_left_out(dynamics) -> bool:
    """A machine whose own reduced moment of inertia the scene takes as zero, turned by a flywheel: a teacher writes
    its equation without the Je term (Je = 0 read as a value the machine has, not as one it is spared)."""
    return dynamics.model.inertia_is_nought and dynamics.flywheel_inertia > 0


def _sum(terms: list[str]) -> str:
    """Inertias added up, in brackets where there are several, so that the sum multiplies dω/dt as a whole."""
    return " + ".join(terms) if len(terms) == 1 else "(" + " + ".join(terms) + ")"


def _driving_half(note: Writer, dynamics) -> list[str]:
    """The inertias that turn with the motor: its rotor reduced to the driving shaft and a clutch's driving half."""
    spec = dynamics.spec.motion
    inertia = [note.text["note_dyn_rotor_symbol"]] if spec.motor.rotor_inertia > 0 else []
    if spec.clutch is not None and spec.clutch.inertia > 0:
        inertia.append(note.text["note_dyn_clutch_symbol"])
    return inertia


def _equation(note: Writer, dynamics) -> None:
    """The equation of motion as it is integrated, each inertia in it with its value, and the integrator."""
    spec = dynamics.spec.motion
    motor, clutch = spec.motor, spec.clutch
    if clutch is None:
        equation = _shaft_equation(note, dynamics)
    else:
        equation = note.t("note_dyn_equation_clutch", machine=_shaft_equation(note, dynamics, slipping=True),
                          driving=note.t("note_dyn_equation_half", inertia=_sum(_driving_half(note, dynamics))),
                          locked=_shaft_equation(note, dynamics))
    # The flywheel's JF as its section and the dynamics drawing write it (189.90, not 189.9).
    terms = note.t("note_dyn_motion_flywheel", value=worked_out(dynamics.flywheel_inertia).replace(".", note.mark)) \
        if dynamics.flywheel_inertia > 0 else ""
    if motor.rotor_inertia > 0:
        terms += note.t("note_dyn_motion_rotor", rotor=note.n(motor.rotor_inertia), ratio=note.n(motor.gear_ratio),
                        value=note.n(motor.reduced_inertia))
    if clutch is not None and clutch.inertia > 0:
        terms += note.t("note_dyn_motion_clutch", value=note.n(clutch.inertia))
    if motor.rotor_inertia == 0:  # missing from the sum, which a reader would otherwise take for an oversight
        terms += note.text["note_dyn_motion_no_rotor"]
    # A machine known by its load diagrams alone has no links, so no weights: its Mr is the resisting diagram's.
    model = dynamics.model
    resistance = note.text["note_dyn_motion_diagram" if model.link == 0 else "note_dyn_motion_loads"]
    key = "note_dyn_motion_no_inertia" if _own_inertia_left_out(dynamics) else \
        "note_dyn_motion_constant" if model.inertia_is_constant else "note_dyn_motion"
    note.para(note.t(key,
                     equation=equation, value=note.n(model.mean_inertia), terms=terms, resistance=resistance,
                     method=dynamics.motion.method, reason=_method_reason(note, dynamics)))


def _clutch(note: Writer, dynamics) -> None:
    """When the clutch's halves first turn together and whether they stay so: a clutch that cannot pass the
    resistance's peaks slips again, in the steady state every turn, and its loss is then a power, not a sum."""
    motion, clutch = dynamics.motion, dynamics.spec.motion.clutch
    given = {"torque": note.n(clutch.torque), "engage": note.n(clutch.engage_at, 4), "energy": note.n(motion.slip_energy)}
    locked = motion.event_time("clutch locked")
    if locked is None:
        note.para(note.t("note_dyn_clutch_slips", **given))
        return
    given.update(locked=note.n(locked, 4), speed=note.n(float(motion.state_at([locked])[1, 0])))
    slips = [when for when, name in motion.events if name == "clutch slips" and when > locked]
    if motion.steady_slip_energy:
        steady = motion.steady
        note.para(note.t("note_dyn_clutch_slips_steady", **given, after=note.n(steady.reached_at, 4),
                         turn=note.n(motion.steady_slip_energy), power=note.n(motion.steady_slip_power)))
    elif slips:
        note.para(note.t("note_dyn_clutch_again", **given, count=Count(len(slips)), last=note.n(slips[-1], 4)))
    else:
        note.para(note.t("note_dyn_clutch", **given))


def _stall(note: Writer, dynamics) -> None:
    """Where the machine stalls and what falls short there: the motor, a clutch slipping at its capacity, or a brake
    applied as the motor drove it; a machine the motor cannot move from where it stands does not start at all."""
    from ..machine_motion import Stall

    motion = dynamics.motion
    angle = dynamics.stall_place(note.text, lambda value: note.n(value, 4))
    mr = dynamics.machine.mr(float(motion.phi[-1]), 0.0)
    resisting = note.n(mr)
    stall = motion.stall
    # The console's advice: not a larger gear ratio where the one given already turns the shaft too slowly.
    too_large = "_gear_too_large" if dynamics.gear is not None and dynamics.gear.too_large else ""
    ratio = note.n(dynamics.spec.motion.motor.gear_ratio)
    if stall is Stall.NEVER_STARTS_BRAKED:
        held = motion.brake.torque
        note.para(note.t("note_dyn_never_starts_braked", angle=angle, torque=note.n(motion.torque_at_rest),
                         resisting=resisting, brake=note.n(held), at=note.n(motion.brake.at, 4),
                         total=note.n(mr + held)))
    elif stall is Stall.NEVER_STARTS:
        note.para(note.t(f"note_dyn_never_starts{too_large}", angle=angle, torque=note.n(motion.torque_at_rest),
                         resisting=resisting, ratio=ratio))
    elif stall is Stall.NEVER_STARTS_CLUTCH:
        note.para(note.t("note_dyn_never_starts_clutch", angle=angle, torque=note.n(motion.clutch.torque),
                         resisting=resisting))
    elif stall is Stall.BRAKE:
        note.para(note.t("note_dyn_stalled_braked", time=note.n(motion.stalled_at, 4), angle=angle,
                         at=note.n(motion.brake.at, 4), brake=note.n(motion.brake.torque), resisting=resisting))
    elif stall is Stall.BRAKE_CLUTCH:
        note.para(note.t("note_dyn_stalled_braked_clutch", time=note.n(motion.stalled_at, 4), angle=angle,
                         at=note.n(motion.brake.at, 4), torque=note.n(motion.clutch.torque),
                         brake=note.n(motion.brake.torque), resisting=resisting))
    elif stall is Stall.CLUTCH:
        note.para(note.t("note_dyn_stalled_clutch", time=note.n(motion.stalled_at, 4), angle=angle,
                         torque=note.n(motion.clutch.torque), resisting=resisting))
    else:
        note.para(note.t(f"note_dyn_stalled{too_large}", time=note.n(motion.stalled_at, 4), angle=angle, ratio=ratio))
    slip = dynamics.speed_slip
    if slip is not None and stall in (Stall.MOTOR, Stall.NEVER_STARTS):  # the console's advice names it first
        note.para(note.t("note_dyn_stalled_rpm_as_rad" if slip.key == "rpm" else "note_dyn_stalled_rad_as_rpm",
                         sized=note.n(slip.sized), square=f"{slip.times_off ** 2:.0f}"))
    torques = dynamics.synchronous_torques_at_rest()
    if slip is None and torques is not None and stall in (Stall.MOTOR, Stall.NEVER_STARTS):
        note.para(note.t("note_dyn_stalled_synchronous", typed=note.n(dynamics.synchronous.typed),
                         nearest=note.n(dynamics.synchronous.nearest), given=note.n(torques[0]),
                         corrected=note.n(torques[1])))


def _run_down(note: Writer, dynamics) -> None:
    """When the machine, its motor switched off, came to rest, and where."""
    motion = dynamics.motion
    note.para(note.t("note_dyn_stopped", off=note.n(dynamics.spec.motion.motor_off_at, 4),
                     time=note.n(motion.stopped_at, 4),
                     angle=dynamics.stall_place(note.text, lambda value: note.n(value, 4))))
    turns = sum(name == "turns back" for _, name in motion.events)
    if turns:
        brake = dynamics.spec.motion.brake
        note.para(note.t("note_dyn_turns_back", torque=note.n(brake.torque if brake is not None else 0.0),
                         count=Count(turns)))


def balancing_section(note: Writer, section: int, result: BalancingResult) -> None:
    """The rotor's masses, their products carried to the correction planes, each plane's polygon closed."""
    from ..rotor_balancing import angles_in_radians, masses_in_grams, on_axis, planes_close, static_couple
    from ..rotor_balancing import lengths_in_millimetres as rotor_lengths

    spec = result.spec
    note.heading(2, note.t("note_balancing"), section)
    rows = [[literal(mass.name), note.n(mass.mass),
             note.n(mass.radius), note.n(mass.angle_deg, 4), note.n(mass.plane), note.n(abs(mass.unbalance))]
            for mass in spec.masses]
    note.table(note.t("note_bal_masses"), note.t("note_bal_masses_header").split(" | "), rows, "lrrrrr")
    # A correction's θ is set on the rotor from the line the masses' θ are counted from, and the same way round: the
    # scene names neither, so the note says that the two agree, and which way the polygons count them.
    note.para(note.t("note_bal_angles"))
    if (lengths := rotor_lengths(spec)) is not None:
        _lengths_caution(note, lengths)
    if (grams := masses_in_grams(spec)) is not None:
        heaviest = max(grams.masses)
        radius, length = grams.cylinder
        note.para(note.t("note_bal_caution_grams", total=note.n(sum(grams.masses)), radius=note.n(radius),
                         length=note.n(length), limit=note.n(grams.limit, 3), mass=note.n(heaviest),
                         kilograms=note.n(heaviest / 1000)))
    if (radians := angles_in_radians(spec)) is not None:
        # Set apart by semicolons: a Russian note's decimal comma would run "0, 1,5708" together.
        note.para(note.t("note_bal_caution_radians", angles="; ".join(note.n(angle) for angle in radians.angles),
                         degrees="; ".join(note.n(math.degrees(angle), 4) for angle in radians.angles)))
    if on_axis(spec) is not None:
        note.para(note.t("note_bal_caution_on_axis"))
    planes = result.planes
    along = [mass.plane for mass in spec.masses]
    if spec.dynamic:
        left, right = planes
        # Two planes balance masses that all turn in one plane as well: the rotor is then no long one.
        masses = (note.t("note_bal_masses_together", z=note.n(along[0])) if len(set(along)) == 1
                  else note.t("note_bal_masses_apart"))
        note.para(note.t("note_bal_dynamic", masses=masses, left=literal(left.name), right=literal(right.name),
                         zl=note.n(left.position), zr=note.n(right.position)))
        header = note.t("note_bal_shares_header", left=literal(left.name), right=literal(right.name)).split(" | ")
        rows = [[literal(mass.label), note.n(abs(mass.unbalance)), note.n(share_left, 4),
                 note.n(abs(mass.unbalance) * share_left),
                 note.n(share_right, 4), note.n(abs(mass.unbalance) * share_right)]
                for mass, share_left, share_right in zip(spec.masses, left.factors, right.factors, strict=True)]
        note.table(note.t("note_bal_shares"), header, rows, "lrrrrr")
    elif (couple := static_couple(result)) is not None:
        # Masses of one plane (a disc corrected on its hub's face) turn at one z, not over "z = 0.1 … 0.1 m".
        where = (note.t("note_bal_along_one", z=note.n(along[0])) if len(set(along)) == 1
                 else note.t("note_bal_along_span", low=note.n(min(along)), high=note.n(max(along))))
        note.para(note.t("note_bal_static_planes", equation=literal(planes[0].equation), along=where,
                         plane=note.n(planes[0].position), moment=note.n(couple)))
    elif len(set(along)) > 1:
        # Masses in several planes whose moments about the correction's plane happen to cancel: no disc.
        note.para(note.t("note_bal_static_planes_even", equation=literal(planes[0].equation), low=note.n(min(along)),
                         high=note.n(max(along)), plane=note.n(planes[0].position)))
    else:
        note.para(note.t("note_bal_static", equation=literal(planes[0].equation)))
    for plane in planes:
        if not plane.needed:
            note.para(note.t("note_bal_none", name=literal(plane.name), vector=literal(plane.vectors[-1].name)))
            continue
        vector = literal(plane.vectors[-1].name)
        # The correction mass is named after its plane, as the drawing names it: mL, mA-A (whose product is (m·r)A-A).
        symbol = literal(f"m{plane.name}")
        value, mass = note.n(plane.mass_radius), ""
        if plane.mass is not None and plane.radius is not None:
            radius = plane.radius
            # The product to as many digits as make product/radius the mass written, in the equation and before it.
            value = shown_operand(note, plane.mass_radius, [(lambda product, radius=radius: product / radius, note.n(plane.mass))])
            mass = note.t("note_bal_mass", symbol=symbol, value=value, radius=note.n(radius), mass=note.n(plane.mass))
        # A disc's one plane has its equation in the paragraph before.
        # The angle to a tenth of a degree, as the drawing writes it: to four digits 210.96° would read 211°.
        angle = angle_in_turn(plane.angle_deg).replace(".", note.mark)
        note.para(note.t("note_bal_plane" if spec.dynamic else "note_bal_closing", name=literal(plane.name),
                         equation=literal(plane.equation), vector=vector, value=value, angle=angle, mass=mass))
    if (close := planes_close(result)) is not None:
        note.para(note.t("note_bal_caution_planes_close", corrections=note.n(close.corrections),
                         ratio=note.n(close.ratio, 3), masses=note.n(close.masses), spacing=note.n(close.spacing),
                         distance=note.n(close.distance)))
    # The residual as results.json writes it (rounding as 0), and the verdict from it.
    force, moment = result.residual
    verdict = "note_bal_residual" + ("" if result.balanced else "_left") + ("" if spec.dynamic else "_static")
    note.para(note.t(verdict, force=note.n(force), moment=note.n(moment),
                     own=note.n(sum(abs(mass.unbalance) for mass in spec.masses))))
    note.figure("rotor_balancing.svg", note.text["bal_title"].format(count=Count(len(result.planes))))


def _shaft(note: Writer, shaft: Shaft, stiffness: str) -> None:
    """The shaft's stiffness at the disc by the formula of its support, with its numbers; ``stiffness`` is k as the
    note writes it."""
    a = shaft.disc_at
    b = shaft.length - a

    def k_of(second: float) -> float:
        if shaft.support == "simply_supported":
            return 3.0 * shaft.modulus * second * shaft.length / (a * a * b * b)
        return 3.0 * shaft.modulus * second / a ** 3

    def in_powers(value: float, digits: int) -> str:
        # Beside E = 2.1·10¹¹ in one product, I = 0.000000125664 had its zeros counted by the reader.
        return power_of_ten(value, digits).replace(".", note.mark) if abs(value) < SMALL_IN_POWERS else note.n(value, digits)

    second = shown_operand(note, shaft.second_moment, [(k_of, stiffness)], in_powers)
    if shaft.diameter is not None:
        note.para(note.t("note_vib_shaft_section", diameter=note.n(shaft.diameter), second=second))
    values = {"modulus": note.n(shaft.modulus), "second": second, "length": note.n(shaft.length), "a": note.n(a),
              "stiffness": stiffness}
    if shaft.support == "simply_supported":
        values["b"] = note.n(b)
    note.para(note.t(f"note_vib_shaft_{shaft.support}", **values))


def shown_operand(note: Writer, value: float, results: list[tuple[Callable[[float], float], str]],
                  write: Callable[[float, int], str] | None = None) -> str:
    """``value`` written to as many digits (five at least) as make each function of ``results``, of the written
    value, give its result as the note writes it: "mL = 1.58/0.05 = 31.599 kg" reads as a wrong sum.  Where
    no few digits do (the other operands are written rounded too), five: ω = 157.07963267948966 is not read.
    ``write`` writes it to so many digits (the note's way, ``note.n``, unless given)."""
    written = write or note.n
    for digits in range(5, MOST_SHOWN_DIGITS + 1):
        text = written(value, digits)
        shown = read_number(note, text)
        if all(_same_written(note, result_of(shown), result) for result_of, result in results):
            return text
    return written(value, 5)


# The most significant digits an operand is written with to make its equations come out as written.
MOST_SHOWN_DIGITS = 8
# Below this a shaft's second moment of area is written as a power of ten, as its E beside it is from 10⁹ on.
SMALL_IN_POWERS = 1e-3


_FROM_SUPERSCRIPT = str.maketrans("⁻⁰¹²³⁴⁵⁶⁷⁸⁹", "-0123456789")


def read_number(note: Writer, text: str) -> float:
    """A number as the note wrote it, read back (2,1·10¹¹ too)."""
    mantissa, _, exponent = text.replace("−", "-").replace(note.mark, ".").partition("·10")
    return float(mantissa) * 10.0 ** int(exponent.translate(_FROM_SUPERSCRIPT)) if exponent else float(mantissa)


def _same_written(note: Writer, value: float, written: str) -> bool:
    """Whether ``value`` written to as many significant digits as ``written`` has (at least) is ``written``; the
    zeros that end a whole number (3030100) may be rounding's."""
    digits = len(written.lstrip("−").replace(note.mark, "").strip("0"))
    return any(note.n(value, count) == written for count in range(max(1, digits), 18))


def vibration_section(note: Writer, section: int, spec: VibrationSpec, response: Response) -> None:
    """From the natural frequency to the amplitude, the force passed to the base, the motion a moving base gives,
    and the isolating mounts.

    Each operand is written to as many digits as make the written operands give the written result
    (:func:`shown_operand`); a value used in several equations is written one way in all of them."""
    from ..vibration import (
        damping_ratio,
        damping_words,
        lengths_in_millimetres,
        mounts_sag,
        near_resonance,
        speed_in_rpm,
        unlikely_damping,
    )
    from .vibration_plots import words_for

    # What excites the machine names the section: a machine on a moving base has no rotating unbalance to speak of.
    moved = spec.base_amplitude is not None
    title = "note_vibration" if not moved else "note_vibration_base" if spec.unbalance == 0 else "note_vibration_both"
    note.heading(2, note.t(title), section)
    mass, unbalance = note.n(spec.mass), note.n(spec.unbalance)
    m = read_number(note, mass)
    natural = note.n(response.natural_frequency)
    ratio = note.n(response.frequency_ratio)
    zeta = note.n(spec.damping_ratio)
    checks_of_k = [(lambda k: math.sqrt(k / m), natural)]
    if spec.damping is not None:
        checks_of_k.append((lambda k: float(damping_ratio(spec.damping, k, m)), zeta))
    stiffness = shown_operand(note, spec.stiffness, checks_of_k)
    omega = shown_operand(note, spec.omega, [(lambda w: w / read_number(note, natural), ratio),
                                             (lambda w: spec.unbalance * w * w, note.n(response.exciting_force))])
    w = read_number(note, omega)
    # Balanced, on a moving base (an instrument on a shaken floor): no unbalance to work out.
    balanced = spec.unbalance == 0 and response.base is not None
    model = "note_vib_model_base" if balanced else "note_vib_model_shaft" if spec.on_shaft else "note_vib_model"
    note.para(note.t(model, mass=mass, stiffness=stiffness, zeta=zeta, unbalance=unbalance,
                     omega=omega, rpm=note.n(spec.omega / RPM)))
    if spec.driver_speed:
        # The table gave no speed: the reader is told whose it is, not left to think it typed.
        note.para(note.t("note_vib_driver_speed", rpm=note.n(spec.omega / RPM), omega=omega))
    if speed_in_rpm(spec) is not None:
        # The file outlives the console: every amplitude and force below follows a speed ten times too high.
        note.para(note.t("note_vib_caution_speed_in_rpm", omega=omega, rpm=note.n(spec.omega / RPM),
                         meant=note.n(spec.omega * RPM)))
    if (unlikely := unlikely_damping(spec)) is not None:
        # The file outlives the console, in the console's words: ζ = 1 read as critical damping (1 % meant?) or ζ
        # over 1 shapes every amplitude and force below, as the ζ of the sentence above.
        note.para(note.t("note_vib_caution_damping", words=damping_words(unlikely, note.text, note.n)))
    # The unbalance and a moving base excite one linear system: each is worked out alone, then the two added.
    both = response.combined
    base_text = "" if response.base is None else note.n(response.base.base_amplitude)
    if both is not None:
        note.para(note.t("note_vib_moving_base_shaft" if spec.on_shaft else "note_vib_moving_base", base=base_text))
    if spec.shaft is not None:
        _shaft(note, spec.shaft, stiffness)
    if (lengths := lengths_in_millimetres(spec)) is not None:
        _lengths_caution(note, lengths)
    if spec.damping is not None:
        note.para(note.t("note_vib_damping", damping=note.n(spec.damping), stiffness=stiffness, mass=mass,
                         zeta=zeta))
    # A critical speed is a rotor's: with none turning, ωn is where the base's motion resonates.
    note.para(note.t("note_vib_natural_base" if balanced else "note_vib_natural", stiffness=stiffness, mass=mass,
                     value=natural, rpm=note.n(response.natural_frequency / RPM), omega=omega, ratio=ratio))
    me_over_m = spec.unbalance / m
    amplitude_checks = [] if balanced else [(lambda q: me_over_m * q, note.n(response.amplitude))]
    if response.base is not None:
        amplitude_checks.append((lambda q: response.base.base_amplitude * q, note.n(response.base.relative)))
    if both is not None:
        strokes = me_over_m + read_number(note, base_text)
        amplitude_checks.append((lambda q: strokes * q, note.n(both.relative)))
    magnification = shown_operand(note, response.magnification, amplitude_checks)
    force = note.n(response.exciting_force)
    # The force passed on is said, not written as a product: TR need only give the base's motion it is written into.
    tr_checks = [] if response.base is None else [(lambda t: response.base.base_amplitude * t,
                                                   note.n(response.base.amplitude))]
    if both is not None:
        moved = spec.unbalance + m * read_number(note, base_text)
        tr_checks.append((lambda t: t * w * w * moved, note.n(both.transmitted_force)))
    if balanced:
        shaken = m * read_number(note, base_text)
        tr_checks.append((lambda t: t * w * w * shaken, note.n(response.base.transmitted_force)))
    tr = shown_operand(note, response.transmissibility, tr_checks)
    if not balanced:
        note.para(note.t("note_vib_amplitude", magnification=magnification, unbalance=unbalance, mass=mass,
                         amplitude=note.n(response.amplitude), millimetres=note.n(response.amplitude * 1000.0),
                         phase=note.n(math.degrees(response.phase), 4)))
        # On a moving base the force the unbalance alone passes is the one it would pass to a base at rest.
        transmitted = "note_vib_transmitted_shaft" if spec.on_shaft else "note_vib_transmitted"
        note.para(note.t(transmitted + ("_alone" if both is not None else ""),
                         unbalance=unbalance, omega=omega, force=force, tr=tr,
                         transmitted=note.n(response.transmitted_force)))
    if response.base is not None:
        base = response.base
        # With no unbalance the scene is an instrument on a shaken floor, as the model's sentence names it.
        note.para(note.t("note_vib_base_instrument" if balanced else "note_vib_base", base=base_text, tr=tr,
                         amplitude=note.n(base.amplitude), phase=note.n(math.degrees(base.phase), 4),
                         magnification=magnification, relative=note.n(base.relative)))
        if balanced:
            # With an unbalance too the two strokes' force is told together below; alone, the base's is the one.
            note.para(note.t("note_vib_base_force_shaft" if spec.on_shaft else "note_vib_base_force", tr=tr,
                             mass=mass, omega=omega, base=base_text, force=note.n(base.transmitted_force)))
    if both is not None:
        first, second = response.amplitude, response.base.amplitude
        note.para(note.t("note_vib_combined", first=note.n(first), first_phase=note.n(math.degrees(response.phase), 4),
                         second=note.n(second), second_phase=note.n(math.degrees(response.base.phase), 4),
                         amplitude=note.n(both.amplitude), phase=note.n(math.degrees(both.phase), 4),
                         low=note.n(abs(first - second)), high=note.n(first + second), unbalance=unbalance,
                         mass=mass, base=base_text, magnification=magnification, relative=note.n(both.relative)))
        note.para(note.t("note_vib_combined_force_shaft" if spec.on_shaft else "note_vib_combined_force", tr=tr,
                         omega=omega, unbalance=unbalance, mass=mass, base=base_text,
                         force=note.n(both.transmitted_force)))
    if (close := near_resonance(spec)) is not None:
        _resonance_caution(note, close)
    if spec.transmissibility is not None and response.isolation_ratio is not None:
        designed = response.isolation_stiffness
        if spec.on_shaft:
            isolating = _shaft_isolation(note, spec, response, mass=mass, omega=omega, stiffness=stiffness,
                                         ratio=ratio, tr=tr)
        else:
            isolating = shown_operand(note, response.isolation_ratio,
                                      [(lambda r: m * (w / r) ** 2, note.n(designed))])
            if spec.damping_ratio > 0:
                # The ratio is found at the same ζ: the mounts need dampers to match.  The present ones,
                # c = 2ζ·√(k·M), keep ζ only on mounts as stiff as now: on softer ones they give more, on stiffer
                # less.
                def damping_for(stiffness: float) -> float:  # c that gives the scene's ζ on mounts that stiff
                    return 2.0 * spec.damping_ratio * math.sqrt(stiffness * spec.mass)

                kept = note.n(float(damping_ratio(damping_for(spec.stiffness), designed, spec.mass)))
                present = "" if kept == zeta else note.t(
                    "note_vib_kept_softer" if designed < spec.stiffness else "note_vib_kept_stiffer", zeta=kept)
                note.para(note.t("note_vib_isolation_damped", wanted=note.n(spec.transmissibility), ratio=isolating,
                                 mass=mass, omega=omega, stiffness=note.n(designed), zeta=zeta,
                                 damping=note.n(damping_for(designed)), kept=present))
            else:
                note.para(note.t("note_vib_isolation", wanted=note.n(spec.transmissibility), ratio=isolating, mass=mass,
                                 omega=omega, stiffness=note.n(designed)))
        # Above √2 a larger r passes less: mounts softer than the designed ones isolate better than asked.  (A shaft
        # that does has been told so: it needs no mounts.)
        if (not spec.on_shaft and response.transmissibility < spec.transmissibility
                and response.frequency_ratio > math.sqrt(2.0)):
            note.para(note.t("note_vib_isolation_already", ratio=ratio, tr=tr, wanted=note.n(spec.transmissibility)))
        if (sagging := mounts_sag(spec)) is not None:
            _sag_caution(note, sagging, isolating)
    words = words_for(spec, note.text) or note.text  # a moving base's plots are captioned as they are titled
    note.figure("vibration_magnification.svg", words["vib_magnification_title"], lead="plot_lead")
    note.figure("vibration_transmissibility.svg", words["vib_transmissibility_title"], lead="plot_lead")


def _shaft_isolation(note: Writer, spec: VibrationSpec, response: Response, *, mass: str, omega: str,
                     stiffness: str, ratio: str, tr: str) -> str:
    """The isolation of a disc on a shaft: M·(ω/r)² is the whole support's stiffness, the shaft's and the mounts'
    under its bearings in series, so the mounts need k_m = k·k_s/(k_s − k); where the shaft alone is no stiffer than
    k it already isolates as asked, and no mount is needed (one in series could only soften it further).
    ``stiffness`` and ``ratio`` are the shaft's k_s and the present r as the note writes them; returns the isolating
    r as written."""
    from ..vibration import damping_ratio

    designed = response.isolation_stiffness
    assert designed is not None and spec.transmissibility is not None and response.isolation_ratio is not None
    m, w, shaft = read_number(note, mass), read_number(note, omega), read_number(note, stiffness)
    mounts = response.isolation_mount_stiffness
    # k is written to as many digits as make k·k_s/(k_s − k) come out as written, and r to as many as make M·(ω/r)²
    # come out as that k.
    total = note.n(designed) if mounts is None else shown_operand(
        note, designed, [(lambda k: k * shaft / (shaft - k), note.n(mounts))])
    isolating = shown_operand(note, response.isolation_ratio, [(lambda r: m * (w / r) ** 2, total)])
    zeta = spec.damping_ratio
    at = "" if zeta == 0 else note.t("note_vib_isolation_shaft_at", zeta=note.n(zeta))
    values = {"wanted": note.n(spec.transmissibility), "ratio": isolating, "mass": mass, "omega": omega,
              "total": total, "shaft": stiffness, "at": at}
    if mounts is None:
        note.para(note.t("note_vib_isolation_shaft_already", present=ratio, tr=tr, **values))
        return isolating
    text = note.t("note_vib_isolation_shaft", mounts=note.n(mounts), **values)
    if zeta > 0:
        # The damping found keeps ζ on the softer support; the present damping, c = 2ζ·√(k_s·M), would give it more.
        kept = note.n(float(damping_ratio(2.0 * zeta * math.sqrt(spec.stiffness * spec.mass), designed, spec.mass)))
        present = "" if kept == note.n(zeta) else note.t("note_vib_kept_shaft", zeta=kept)
        text += note.t("note_vib_isolation_shaft_damped", damping=note.n(2.0 * zeta * math.sqrt(designed * spec.mass)),
                       kept=present)
    note.para(text)
    return isolating


def _lengths_caution(note: Writer, lengths: LengthsInMillimetres) -> None:
    """What the command line warns of lengths that look typed in millimetres, said in words under the data they are
    in: the note's reader has no scene to look its keys up in, and a 30 m shaft must not read as if nothing were
    amiss."""
    found = []
    for item in lengths.found:
        values = {"name": item.name, "value": note.n(item.value), "limit": note.n(item.limit, 3),
                  "other": note.n(item.other), "other_name": item.other_name}
        if item.kind in ("mixed", "flat_rotor", "flat_rotor_correction", "thin_disc"):
            values["ratio"] = note.n(item.value / item.other, 3)
        elif item.kind == "rotor_length":
            values["apart"] = note.n(item.value - item.other)
        elif item.kind == "base":
            values["speed"] = note.n(item.value * item.other, 4)
        elif item.kind == "unbalance":
            values["distance"] = note.n(item.value / item.other)
        found.append(note.t(f"note_len_{item.kind}", **values))
    from ..rotor_lengths import SOME_IN_MILLIMETRES

    mixed = any(item.kind in SOME_IN_MILLIMETRES for item in lengths.found)
    key = "_speed" if lengths.only_speed else "_mixed" if mixed else ""
    note.para(note.t("note_lengths_caution" + key, found=note.text["note_len_separator"].join(found)))


def _resonance_caution(note: Writer, close: NearResonance) -> None:
    """What the command line warns of a speed near resonance, said where the amplitude is: the file outlives the
    console."""
    share = note.n(close.percent_off, 2)
    ratio = note.n(close.ratio)
    # r = 1 as written is resonance itself, not "within 0 % of" it.
    at = "_at" if ratio == note.n(1.0) else ""
    # An instrument is shaken by its base: no speed of its own to run away from resonance, and it moves X/Y times
    # as far as the base, not by a magnification of an unbalance it has not.
    shaken = "_base" if close.instrument else ""
    if close.zeta > 0:
        note.para(note.t(f"note_vib_caution_resonance{at}{shaken}", share=share, ratio=ratio, zeta=note.n(close.zeta),
                         magnification=note.n(close.magnification), tr=note.n(close.transmissibility)))
    else:
        note.para(note.t(f"note_vib_caution_resonance{at}_undamped{shaken}", share=share, ratio=ratio))


def _sag_caution(note: Writer, sagging: MountsSag, ratio: str) -> None:
    """Mounts the formulas give but no spring could be (a sag of metres), with the ways to mounts that could:
    without it the note offers them as a design.  ``ratio`` is r as the isolation paragraph writes it."""
    from ..vibration import MOST_MOUNT_SAG

    limit = note.n(MOST_MOUNT_SAG * 1000.0)
    at = "" if sagging.zeta == 0 else note.t("note_vib_caution_sag_damped", zeta=note.n(sagging.zeta),
                                             undamped=note.n(sagging.undamped_ratio))
    # Under a shaft's bearings the mounts sag what the shaft's own bending leaves of g·r²/ω².
    text = note.t("note_vib_caution_sag_shaft" if sagging.shaft_sag > 0 else "note_vib_caution_sag",
                  stiffness=note.n(sagging.stiffness), sag=note.n(sagging.sag, 3), limit=limit,
                  wanted=note.n(sagging.wanted), ratio=ratio, at=at, own=note.n(sagging.shaft_sag, 3))
    if sagging.undamped_sag is not None:
        text += note.t("note_vib_caution_sag_undamped", sag=note.n(sagging.undamped_sag, 3))
    if sagging.root_two_sag is not None:
        text += note.t("note_vib_caution_sag_no_mount", limit=limit, sag=note.n(sagging.root_two_sag, 3))
    # The bounds are written as found, rounded to their safe side, not to the note's digits.
    ways = []
    if sagging.most_damping is not None:
        ways.append(note.t("note_vib_caution_way_damping", value=sagging.most_damping.replace(".", note.mark)))
    if sagging.least_transmissibility is not None:
        # The least TR holds at the scene's ζ alone: the console says "at ζ = 8", and so must the note.
        damped = "_damped" if sagging.zeta > 0 else ""
        ways.append(note.t(f"note_vib_caution_way_transmissibility{damped}", zeta=note.n(sagging.zeta),
                           value=sagging.least_transmissibility.replace(".", note.mark)))
    ways.append(note.t("note_vib_caution_way_speed", value=sagging.least_rpm.replace(".", note.mark),
                       rpm=note.n(sagging.rpm)))
    text += note.t("note_vib_caution_sag_ways", limit=limit, ways=note.text["note_vib_caution_or"].join(ways))
    note.para(text)


__all__ = ["balancing_section", "vibration_section"]
