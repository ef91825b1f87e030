"""The note's sections on balancing the rotor and on the vibration its unbalance causes.

Each is worked out as a student's note works it: the equation, the numbers put into it, the result with
its unit.  The balancing goes by the polygon of each correction plane (a long rotor's mass-radius
products first carried to its two planes, as a load to two supports); the vibration from the natural
frequency to the amplitude, the force the mounts pass to the base and the mounts that would isolate it.
The sections are written by the note's own writer, whose numbering, tables and language they share.
"""

from __future__ import annotations

import math
from typing import Protocol

from ..rotor_balancing import BalancingResult
from ..vibration import RPM, Response, VibrationSpec


class Writer(Protocol):
    """What a section needs of the note it is written into."""

    def t(self, key: str, **values: object) -> str: ...
    def n(self, value: float, digits: int = 5) -> str: ...
    def heading(self, level: int, title: str) -> None: ...
    def para(self, *lines: str) -> None: ...
    def table(self, caption: str | None, header: list[str], rows: list[list[str]], align: str | None = None) -> None: ...


def balancing_section(note: Writer, section: int, result: BalancingResult) -> None:
    """The rotor's masses, their products carried to the correction planes, each plane's polygon closed."""
    spec = result.spec
    note.heading(2, f"{section}. {note.t('note_balancing')}")
    rows = [[mass.name, note.n(mass.mass),
             note.n(mass.radius), note.n(mass.angle_deg, 4), note.n(mass.plane), note.n(abs(mass.unbalance))]
            for mass in spec.masses]
    note.table(note.t("note_bal_masses"), note.t("note_bal_masses_header").split(" | "), rows, "lrrrrr")
    planes = result.planes
    if spec.dynamic:
        left, right = planes
        note.para(note.t("note_bal_dynamic", left=left.name, right=right.name, zl=note.n(left.position),
                         zr=note.n(right.position)))
        header = note.t("note_bal_shares_header", left=left.name, right=right.name).split(" | ")
        rows = [[mass.label, note.n(abs(mass.unbalance)), note.n(share_left, 4), note.n(abs(mass.unbalance) * share_left),
                 note.n(share_right, 4), note.n(abs(mass.unbalance) * share_right)]
                for mass, share_left, share_right in zip(spec.masses, left.factors, right.factors, strict=True)]
        note.table(note.t("note_bal_shares"), header, rows, "lrrrrr")
    else:
        note.para(note.t("note_bal_static", equation=planes[0].equation))
    for plane in planes:
        if not plane.needed:
            note.para(note.t("note_bal_none", name=plane.name))
            continue
        value, vector = note.n(plane.mass_radius), plane.vectors[-1].name
        # The correction mass is named as its product is (mLrL: mL), a long plane name's as mb.
        symbol = f"m{plane.name}" if vector == f"m{plane.name}r{plane.name}" else "mb"
        mass = "" if plane.mass is None else note.t("note_bal_mass", symbol=symbol, value=value,
                                                     radius=note.n(plane.radius), mass=note.n(plane.mass))
        # A disc's one plane has its equation in the paragraph before.
        note.para(note.t("note_bal_plane" if spec.dynamic else "note_bal_closing", name=plane.name,
                         equation=plane.equation, vector=vector, value=value, angle=note.n(plane.angle_deg, 4),
                         mass=mass))
    if spec.dynamic:
        note.para(note.t("note_bal_residual", force=note.n(abs(result.residual_force)),
                         moment=note.n(abs(result.residual_moment))))
    else:
        note.para(note.t("note_bal_residual_static", force=note.n(abs(result.residual_force))))


def vibration_section(note: Writer, section: int, spec: VibrationSpec, response: Response) -> None:
    """From the natural frequency to the amplitude, the force passed to the base, the motion a moving base gives,
    and the isolating mounts."""
    note.heading(2, f"{section}. {note.t('note_vibration')}")
    mass, stiffness, omega = note.n(spec.mass), note.n(spec.stiffness), note.n(spec.omega)
    unbalance = note.n(spec.unbalance)
    # Balanced, on a moving base (an instrument on a shaken floor): no unbalance to work out.
    balanced = spec.unbalance == 0 and response.base is not None
    note.para(note.t("note_vib_model_base" if balanced else "note_vib_model", mass=mass, stiffness=stiffness,
                     zeta=note.n(spec.damping_ratio), unbalance=unbalance, omega=omega, rpm=note.n(spec.omega / RPM)))
    natural = note.n(response.natural_frequency)
    note.para(note.t("note_vib_natural", stiffness=stiffness, mass=mass, value=natural,
                     rpm=note.n(response.natural_frequency / RPM), omega=omega, ratio=note.n(response.frequency_ratio)))
    magnification = note.n(response.magnification)
    if not balanced:
        note.para(note.t("note_vib_amplitude", magnification=magnification, unbalance=unbalance, mass=mass,
                         amplitude=note.n(response.amplitude), millimetres=note.n(response.amplitude * 1000.0),
                         phase=note.n(math.degrees(response.phase), 4)))
        note.para(note.t("note_vib_transmitted", unbalance=unbalance, omega=omega,
                         force=note.n(response.exciting_force), tr=note.n(response.transmissibility),
                         transmitted=note.n(response.transmitted_force)))
    if response.base is not None:
        base = response.base
        note.para(note.t("note_vib_base", base=note.n(base.base_amplitude), tr=note.n(response.transmissibility),
                         amplitude=note.n(base.amplitude), phase=note.n(math.degrees(base.phase), 4),
                         magnification=magnification, relative=note.n(base.relative)))
    if spec.transmissibility is not None and response.isolation_ratio is not None:
        ratio = note.n(response.isolation_ratio)
        note.para(note.t("note_vib_isolation", wanted=note.n(spec.transmissibility), ratio=ratio, mass=mass,
                         omega=omega, stiffness=note.n(response.isolation_stiffness)))


__all__ = ["balancing_section", "vibration_section"]
