"""The initial data of the note beyond the links' dimensions and the driver's motion: the links' masses, centres
of mass and moments of inertia, the external loads and when they act, g, the pairs' friction and what the
dynamics is given (δ, a mean speed, the flywheel's shaft, the motor).

A course project's note (пояснительная записка, 课程设计说明书) states the whole assignment under its initial
data; the force analysis and the dynamics then work from values the reader has already seen, in the same symbols
(m, JS, G, F4, M3, δ)."""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import Protocol

from ..loads import external_names
from ..scene import OTHER_SENSE, LoadSpec, Scene
from ..units import RPM


class DataWriter(Protocol):
    scene: Scene
    text: Mapping[str, str]

    def t(self, key: str, **values: object) -> str: ...

    def n(self, value: float, digits: int = 5) -> str: ...


def mass_rows(note: DataWriter) -> list[list[str]]:
    """A row for each link given a mass or a moment of inertia: m, its centre as the scene names it (the lengths
    table gives where that point lies on its link, lAS3), JS; a dash where the scene gives none."""
    rows = []
    for number, spec in sorted(note.scene.links.items()):
        if spec.mass <= 0 and spec.inertia <= 0:
            continue
        rows.append([str(number), note.n(spec.mass) if spec.mass > 0 else "—", spec.centre or "—",
                     note.n(spec.inertia) if spec.inertia > 0 else "—"])
    return rows


def mass_header(note: DataWriter) -> list[str]:
    text = note.text
    return [text["column_link"], f"m, {text['unit_kg']}", text["column_centre"], f"JS, {text['unit_kg_m2']}"]


def data_rows(note: DataWriter) -> list[list[str]]:
    """(description, symbol, value) of g where the weights are taken, each external load, each pair's friction and
    the dynamics' data, in the order the note works with them."""
    scene, text = note.scene, note.text
    rows = []
    if any(spec.mass > 0 for spec in scene.links.values()):
        rows.append([text["note_data_gravity"], "g", f"{note.n(scene.gravity)} {text['unit_m_per_s2']}"])
    for name, load in zip(external_names(scene.loads), scene.loads, strict=True):
        rows.append([_load_description(note, load), name, _load_value(note, load)])
    rows.extend(_friction_rows(note))
    rows.extend(_dynamics_rows(note))
    return rows


def data_header(note: DataWriter) -> list[str]:
    return [note.text["column_description"], note.text["column_symbol"], note.text["column_value"]]


def data_caption(note: DataWriter) -> str:
    """Named for what the table holds: a scene of a flywheel alone has no force analysis to give data for."""
    scene = note.scene
    forces = bool(scene.loads or scene.friction or any(spec.mass > 0 for spec in scene.links.values()))
    dynamics = bool(_dynamics_rows(note))
    return note.t("note_data_caption_" + ("both" if forces and dynamics else "dynamics" if dynamics else "forces"))


def _load_description(note: DataWriter, load: LoadSpec) -> str:
    if load.spring:
        return note.t("note_data_spring", link=load.link, point=load.point, line=f"{load.along}{load.point}")
    kind = "moment" if load.kind == "moment" else "force"
    return note.t(f"note_data_{kind}{'_resisting' if load.resisting else ''}", link=load.link, point=load.point)


def _load_value(note: DataWriter, load: LoadSpec) -> str:
    """Its value as the scene gives it, its line or sense, and when it acts."""
    text = note.text
    unit = text["newton_metre" if load.kind == "moment" else "newton"]
    if load.spring:
        parts = [note.t("note_data_spring_value", stiffness=note.n(load.stiffness),
                        free_length=note.n(load.free_length))]
    else:
        # A resisting load's sign is the motion's it opposes, as the force analysis and its diagrams take it.
        value = note.n(abs(load.value) if load.resisting else load.value)
        parts = [note.t("note_data_largest", value=value, unit=unit) if load.diagram else f"{value} {unit}"]
    if load.kind == "moment":
        parts.append(note.t("note_data_against_turning", link=load.link) if load.resisting
                     else text["forces_sense_moment"])
    else:
        if load.along is not None and not load.spring:
            parts.append(note.t("note_data_along", line=f"{load.along}{load.point}"))
        elif load.angle_deg is not None:
            parts.append(note.t("note_data_at_angle", angle=note.n(load.angle_deg)))
        if load.resisting:
            parts.append(note.t("note_data_against_motion", point=load.point))
    parts.append(_when(note, load))
    return text["semicolon"].join(parts)


def _when(note: DataWriter, load: LoadSpec) -> str:
    """When the load acts: always, over a stroke, over a window of the working stroke, or by its diagram over the
    shares it spans; of its own stroke (a second piston's, the gas's on each stroke of one piston) where the scene
    gives one other than the working link's working stroke, which its shares are then counted along."""
    working, own = note.scene.positions.working, load.stroke
    if own is not None and (working is None or (own.link, own.sense) != (working.link, working.sense)):
        sense = own.sense if load.during != "idle" else OTHER_SENSE[own.sense]
        stroke = {"link": own.link, "sense": note.text[f"note_data_sense_{sense}"]}
        suffix = "_own"
    else:
        stroke, suffix = {}, ""
    if load.diagram:
        return note.t("note_data_diagram" + suffix, start=note.n(load.diagram[0][0]), end=note.n(load.diagram[-1][0]),
                      **stroke)
    if load.during == "always":
        return note.text["note_data_always"]
    if isinstance(load.during, str):
        return note.t("note_data_working_own", **stroke) if suffix else note.text[f"note_data_{load.during}"]
    start, end = load.during
    return note.t("note_data_window" + suffix, start=note.n(start), end=note.n(end), **stroke)



def _friction_rows(note: DataWriter) -> list[list[str]]:
    """f of each pair, named by its joint (by its links as well where two pairs with friction share the joint), and
    the journal's radius or the V-guide's half-angle that goes with it."""
    text, friction = note.text, note.scene.friction
    joints = [spec.joint for spec in friction]
    rows = []
    for spec in friction:
        shared = joints.count(spec.joint) > 1 and spec.links is not None
        suffix = f"{spec.links[0]}{spec.links[1]}" if shared else spec.joint
        if spec.links is not None:
            described = note.t("note_data_friction_links", joint=spec.joint, first=spec.links[0],
                               second=spec.links[1])
        else:
            described = note.t("note_data_friction", joint=spec.joint)
        rows.append([described, f"f{suffix}", note.n(spec.f)])
        if spec.radius is not None:
            rows.append([note.t("note_data_journal", joint=spec.joint), f"r{suffix}",
                         f"{note.n(spec.radius)} {text['unit_m']}"])
        if spec.groove_half_angle is not None:
            rows.append([note.t("note_data_groove", joint=spec.joint), f"θ{suffix}",
                         f"{note.n(math.degrees(spec.groove_half_angle))}°"])
    return rows


def _dynamics_rows(note: DataWriter) -> list[list[str]]:
    """What ``[dynamics]`` gives a linkage's flywheel and equation of motion; the driver's own speed, which the
    table of dimensions already gives, not again."""
    spec, text = note.scene.dynamics, note.text
    if spec is None:
        return []
    rows = []
    if spec.delta is not None:
        rows.append([text["note_data_delta"], "δ", note.n(spec.delta)])
    if spec.speed_key == "rpm":
        rows.append([text["note_data_mean_rpm"], "n", f"{note.n(spec.omega / RPM)} {text['unit_rpm']}"])
    elif spec.speed_key == "omega":
        rows.append([text["note_data_mean_omega"], text["note_data_omega_symbol"],
                     f"{note.n(spec.omega)} {text['unit_rad_per_s']}"])
    if spec.flywheel_shaft_rpm is not None:
        rows.append([text["note_data_flywheel_shaft"], "n′", f"{note.n(spec.flywheel_shaft_rpm)} {text['unit_rpm']}"])
    if spec.motion is not None:
        rows.extend(_motor_rows(note, spec.motion.motor))
    return rows


def _motor_rows(note: DataWriter, motor) -> Sequence[list[str]]:
    # Imported here, where a scene's motor has loaded the equation of motion already: the package brings scipy's
    # integrators and optimisers with it, which at the module's head every run's note loaded (0.4 s of a cold run
    # of a linkage without [dynamics]).
    from ..machine_motion import ConstantTorque, KlossMotor

    text = note.text
    if isinstance(motor, ConstantTorque):
        rows = [[text["note_data_motor_constant"], "M", f"{note.n(motor.torque)} {text['newton_metre']}"]]
    elif isinstance(motor, KlossMotor):
        synchronous_rpm = motor.synchronous_speed / RPM
        rows = [[text["note_data_motor_kloss"], "—", note.t(
            "note_data_motor_kloss_value", power=note.n(motor.power), synchronous_rpm=note.n(synchronous_rpm),
            rated_rpm=note.n(synchronous_rpm * (1.0 - motor.rated_slip)), overload=note.n(motor.overload))]]
    else:
        rows = [[text["note_data_motor_linear"], "—", note.t(
            "note_data_motor_linear_value", stall=note.n(motor.stall_torque), no_load=note.n(motor.no_load),
            rpm=note.n(motor.no_load / RPM))]]
    # A motor on the driving shaft itself has no gear, and a rotor of no inertia adds none to the machine's.
    if motor.gear_ratio != 1:
        rows.append([text["note_data_gear"], text["note_data_gear_symbol"], note.n(motor.gear_ratio)])
    if motor.rotor_inertia > 0:
        rows.append([text["note_data_rotor"], text["note_data_rotor_symbol"],
                     f"{note.n(motor.rotor_inertia)} {text['unit_kg_m2']}"])
    return rows
