"""Lengths typed in millimetres where ``[balancing]`` and ``[vibration]`` ask for metres: a radius of 80 m, a shaft
30 m thick.  The rotor and the machine still work out, every result a thousand times off (correction masses of
1680 kg for a 5 kg rotor), so the run warns, naming each key with its value, as the linkage's ``lengths-in-mm`` does
(:mod:`graphplan.length_units`).  The limits are beyond every real machine, so a true one is never told its lengths
are millimetres; a length in millimetres is caught where it passes them.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from .units import MIXED_RATIO, millimetres_question, solid_steel_cylinder

# The largest rotors are wind turbines', whose blade tips turn some 120 m from the axis (a hydro-turbine runner or a
# generator rotor, balanced in planes, a few metres): a radius or an eccentricity over LARGEST_RADIUS_M is no
# machine's.
LARGEST_RADIUS_M = 150.0
# The longest rotors balanced in two planes, turbine-generator rotors and paper-machine rolls, are some 10–15 m
# long, and no shaft spans more between its bearings (a ship's propeller shaft has bearings every few metres).
LONGEST_ROTOR_M = 50.0
# The thickest shafts, a hydro-generator's or a large ship's, are 1–2 m across; a shaft given by its second moment
# of area is judged by a round one's, I = π·d⁴/64.
THICKEST_SHAFT_M = 5.0
LARGEST_SECOND_MOMENT_M4 = math.pi * THICKEST_SHAFT_M ** 4 / 64.0
# A correction mass is fixed near the rim, where it does the most: a mass turning MIXED_RATIO (units') times farther
# out than the corrections is one in millimetres among metres, as a linkage's length that many times another is.
# (The other way round is real: a disc's eccentricity of 0.1 mm, corrected at 0.2 m.)
# The unbalanced mass of a machine on its mounts turns on a rotor that reaches out to it, and the machine (its mass
# includes the rotor) weighs at least LIGHTEST_AT_ONE_METRE·(e / 1 m)**LIGHTNESS_EXPONENT: a machine lighter than
# that has its eccentricity in millimetres, e = 5 meant as 5 mm (112 kg at e = 5 m).  A rotor's blades or spokes fill
# little of the circle they sweep and are plastic, aluminium or carbon, so no sheet filling it bounds the mass (a 1 mm
# steel sheet, 24.7 kg at e = 1 m, outweighed a 5 kg ceiling fan reaching 0.66 m); and a larger rotor is built
# thicker as well as wider, its mass growing faster than the circle it sweeps (e²) and slower than its volume at
# one shape (e³): wind turbines' blades, for one, as R^2.5.  The lightest real machines for their reach, as mass
# over e^2.5: a 450-size model helicopter (0.7 kg, 0.355 m) 9, a propeller on its motor (67 g, 0.127 m) 12, a
# plastic fan (0.5 kg, 0.3 m) 10, a road bicycle's wheel (1 kg, 0.336 m) 15, a ceiling fan (5 kg, 0.66 m) 14, a
# micro wind turbine (6 kg, 0.585 m) 23, an ultralight gyroplane (some 110 kg, 3 m) 7, NREL's 5 MW turbine with its
# nacelle (350 t, 63 m) 11, the largest turbines (some 600 t at 110 m) 5: all above 2, the slip of a 100 kg machine
# with e = 5 mm below it.  (Record-breaking human-powered helicopters, 50 kg under rotors 10 m long, are not
# machines on mounts.)
LIGHTEST_AT_ONE_METRE = 2.0
LIGHTNESS_EXPONENT = 2.5
# A rotor balanced in two planes is a long one (a shaft with its discs, a drum, a crankshaft); a wide disc is
# balanced in one.  Its masses turn within a few times its length along the axis of it (a car's wheel some 2, a fan's
# impeller 5 or so): a mass FLATTEST_ROTOR times farther out than the masses and planes lie apart along the axis is
# one whose radius was typed in millimetres among planes in metres.
FLATTEST_ROTOR = 20.0
# A rotor balanced in one plane is a disc (a wheel, a pulley, a fan's impeller, a grinding wheel): where its masses
# lie in planes apart along its axis, they lie within its thickness, and no disc is thinner than THINNEST_DISC of its
# radius (a circular saw's blade or a cut-off wheel, the thinnest, some 1/60–1/120).  A mass that far out has its
# radius in millimetres among planes in metres: the two-plane rotor's 20 would tell a grinding wheel or a flywheel
# its radius is millimetres.  A disc with every mass in one plane gives no length along its axis to judge by.
THINNEST_DISC = 200.0
# A rotor's masses are bolted, welded or cast on it, within its body, and no body is heavier than solid steel: the
# masses of one rotor together weigh at most a steel cylinder ROTOR_REACH times as large in radius as the farthest
# out a mass or a correction turns, R, and ROTOR_REACH times as long as its masses and planes span along the axis, L
# (a disc's, shorter than R, taken as R: a rim, a hub and the web between reach farther along the axis than the
# masses a textbook puts in one plane), ρ·π·(2R)²·2·max(L, R): 197 kg for a disc of R = 0.1 m, 148 kg for a rotor
# of R = 0.05 m over L = 0.3 m.  Radius and length are weighed apart, for a long rotor's largest length, its span,
# would bound it by a cylinder as wide as it is long (8·π·ρ·L³, 5330 kg over 0.3 m), which masses in grams on a
# rotor some 0.1 m across (200, 150, 250 for 0.2, 0.15, 0.25 kg) pass.  The radii are where the masses' centres
# turn, not the rim, and a textbook's "mass" is often a whole disc off its centre, hence twice: Khurmi's four masses
# of 1000 kg in one plane within 0.3 m of the axis, among the heaviest for their size of textbook exercises, fill a
# fifth of it (5330 kg), his shaft's 1100 kg within 0.1 m of the axis over 0.7 m along it four fifths (1380 kg), the
# rotor starter's 42 kg within 0.06 m over 0.22 m a quarter (156 kg).  Where the masses' radii are eccentricities
# (:func:`radii_are_eccentricities`), the scene gives no radius of the rotor at all and its masses are not weighed.
# Without a correction_radius it gives no rim either, which lumps may turn well inside (Khurmi's shaft's at 0.06–0.08
# m, corrected at 0.1 m): the rotor is then taken as large as the span, 8·π·ρ·max(R, L)³.  A rotor of one mass gives
# it no bound at all: its radius may be a heavy disc's eccentricity (a 500 kg flywheel 2 mm off its axis).
ROTOR_REACH = 2.0
# Masses typed in grams are lumps fixed out where they turn (test masses, bolts, balancing weights), and a lump off the
# axis lies within its radius of its centre: solid steel filling that circle over the rotor's length holds it, and a
# rotor's lumps are far lighter still (the 200, 150 and 250 g of a rotor 0.3 m long, as steel, reach 9 mm from the
# axis, well inside the 30–50 mm they turn at).  So read as grams, a thousandth of what they are typed as, the masses
# of a slip reach as solid steel no farther from the axis than the farthest of them turns.  Masses that reach farther
# even so are bodies round the axis whatever their unit, discs keyed off their centres, their radii eccentricities
# that grams would not explain: two 500 kg discs 2 mm off their axis on a shaft 0.3 m long, as 1 kg of steel, reach
# 11.6 mm.  Their own radius is not in the scene, nor is it a correction_radius beside them (0.01 m: a collar on the
# shaft, or a hub, may carry the corrections), and the refusal of a correction radius too small weighs them as kg, at
# the size that holds them (:func:`solid_steel_reach`).
GRAMS_PER_KILOGRAM = 1000.0
# The strongest earthquakes move the ground at some 1–3 m/s at their peak, shaking tables a few m/s: a base moving
# faster than FASTEST_BASE_M_S (Y·ω) has its amplitude in millimetres, or ω in rev/min.
FASTEST_BASE_M_S = 20.0


# The findings of some lengths in millimetres among others in metres: dividing every length would spoil the rest.
SOME_IN_MILLIMETRES = frozenset({"mixed", "flat_rotor", "flat_rotor_correction", "thin_disc"})


def lightest_rotor(eccentricity: float) -> float:
    """The least mass (kg) of a machine whose rotor reaches ``eccentricity`` (m) from its axis, below every real
    one's for its reach (:data:`LIGHTEST_AT_ONE_METRE`, :data:`LIGHTNESS_EXPONENT`)."""
    return LIGHTEST_AT_ONE_METRE * eccentricity ** LIGHTNESS_EXPONENT


def rotor_length(radius: float, span: float) -> float:
    """The length (m) a rotor turning within ``radius`` of its axis, its masses and planes ``span`` apart along it, is
    weighed by: its span, or a disc's radius where the span is shorter."""
    return max(span, radius)


def bounding_cylinder(radius: float, span: float) -> tuple[float, float]:
    """The radius and length (m) of the cylinder no such rotor's masses outweigh as solid steel: :data:`ROTOR_REACH`
    times its radius and :data:`ROTOR_REACH` times its :func:`rotor_length`."""
    return ROTOR_REACH * radius, ROTOR_REACH * rotor_length(radius, span)


def heaviest_rotor(radius: float, span: float) -> float:
    """The most (kg) the masses of a rotor weigh together that turn within ``radius`` (m) of its axis, its masses and
    planes ``span`` (m) apart along it: solid steel filling its :func:`bounding_cylinder`, ρ·π·(2R)²·2·max(L, R)."""
    return solid_steel_cylinder(*bounding_cylinder(radius, span))


def solid_steel_reach(mass: float, span: float) -> float:
    """How far (m) from its axis a rotor reaches at the least that holds ``mass`` (kg) over ``span`` (m) along it:
    the radius of solid steel, the densest body a rotor is, weighing ``mass`` as a cylinder of its
    :func:`rotor_length` (so that :func:`heaviest_rotor` of that radius is ``ROTOR_REACH``³ times ``mass``)."""
    disc = (mass / solid_steel_cylinder(1.0, 1.0)) ** (1.0 / 3.0)
    return disc if disc >= span else math.sqrt(mass / solid_steel_cylinder(1.0, span))


def radii_are_eccentricities(mass: float, span: float, farthest: float) -> bool:
    """Whether masses weighing ``mass`` (kg) together over ``span`` (m) along the axis, the farthest of them turning
    ``farthest`` (m) from it, are bodies round the axis even read as grams, their radii eccentricities: solid steel
    weighing a thousandth of them reaches farther from the axis (:func:`solid_steel_reach`) than they turn
    (:data:`GRAMS_PER_KILOGRAM`)."""
    return solid_steel_reach(mass / GRAMS_PER_KILOGRAM, span) > farthest


@dataclass(frozen=True)
class Implausible:
    """One length of the scene that no machine has, as metres.

    ``kind`` names the check (``radius``, ``correction_radius``, ``mixed``, ``flat_rotor``, ``thin_disc``,
    ``rotor_length``, ``eccentricity``, ``unbalance``, ``light_machine``, ``diameter``, ``second_moment``, ``span``,
    ``base``); ``key`` its key path and ``value`` what it gives; ``limit`` the most a machine has.  ``name`` is the mass's or the plane's name it
    belongs to; ``other_key`` and ``other`` the second key it is judged against (``mixed``: the correction radius;
    ``rotor_length``: the farthest plane; ``flat_rotor``, ``thin_disc``: the masses' and planes' span along the axis,
    ``limit`` the ratio; ``light_machine``: the machine's mass, ``limit`` the lightest machine's for its reach;
    ``unbalance``: the machine's mass, whose whole off the axis m·e needs ``value``/``other`` m), or
    for ``base`` ω (rad/s).
    """

    kind: str
    key: str
    value: float
    limit: float
    name: str = ""
    other_key: str = ""
    other: float = 0.0
    other_name: str = ""

    @property
    def detail(self) -> str:
        """The finding in English, as the command line prints it."""
        given = f"{self.key} = {self.value:g}"
        if self.kind == "mixed":
            return (f"{given} m is {self.value / self.other:.3g} times {self.other_key} = {self.other:g} m (a mass "
                    f"turning more than {MIXED_RATIO:g} times farther out than its correction)")
        if self.kind == "rotor_length":
            return (f"{given} m lies {abs(self.value - self.other):.4g} m from {self.other_key} = {self.other:g} m, "
                    f"farther apart than any rotor's planes (over {self.limit:g} m)")
        if self.kind == "base":
            return (f"{given} m at ω = {self.other:.4g} rad/s moves the base at Y·ω = {self.value * self.other:.4g} "
                    f"m/s, faster than any floor or shaking table (over {self.limit:g} m/s)")
        if self.kind == "unbalance":
            return (f"{given} kg·m needs the whole machine, {self.other_key} = {self.other:g} kg, "
                    f"{self.value / self.other:.6g} m from the axis, farther than any rotor's radius (over "
                    f"{self.limit:g} m)")
        if self.kind == "light_machine":
            return (f"{given} m puts the unbalanced mass that far from the axis, and the lightest machines that "
                    f"reach so far (a propeller on its motor, a fan, a bicycle's wheel, a wind turbine) weigh at "
                    f"least {self.limit:.3g} kg, more than the whole machine, {self.other_key} = {self.other:g} kg "
                    f"(as millimetres, {self.key} = {self.value / 1000:g})")
        if self.kind in ("flat_rotor", "flat_rotor_correction"):
            turning = "masses" if self.kind == "flat_rotor" else "corrections"
            return (f"{given} m is {self.value / self.other:.3g} times the rotor's length along its axis, "
                    f"{self.other:g} m from {self.other_key} (a rotor balanced in two planes is long: its {turning} "
                    f"turn no farther than {self.limit:g} times its length from the axis; as millimetres, "
                    f"{self.key} = {self.value / 1000:g})")
        if self.kind == "thin_disc":
            return (f"{given} m is {self.value / self.other:.3g} times the {self.other:g} m its masses and correction "
                    f"plane lie apart along the axis, from {self.other_key} (a rotor balanced in one plane is a disc, "
                    f"its masses within its thickness, and no disc's radius is over {self.limit:g} times its "
                    f"thickness; as millimetres, {self.key} = {self.value / 1000:g})")
        if self.kind == "second_moment":
            return (f"{given} m⁴ is more than any shaft's (over {self.limit:.3g} m⁴, a {THICKEST_SHAFT_M:g} m round "
                    "shaft's)")
        what = {"radius": "a radius larger than any rotor's", "correction_radius": "a radius larger than any rotor's",
                "eccentricity": "larger than any rotor's radius", "diameter": "thicker than any shaft",
                "span": "longer than any shaft between its bearings"}[self.kind]
        return f"{given} m is {what} (over {self.limit:g} m)"


@dataclass(frozen=True)
class LengthsInMillimetres:
    """The scene's lengths that are implausible as metres (:class:`Implausible`), as lengths typed in millimetres
    make them."""

    found: tuple[Implausible, ...]
    code = "lengths-in-mm"

    @property
    def only_speed(self) -> bool:
        """Whether a moving base's speed alone gives them away: ω in rev/min would too."""
        return all(item.kind == "base" for item in self.found)

    @property
    def detail(self) -> str:
        """The warning in a line (English, as the command line prints it)."""
        unless = ", unless ω is too large: it is in rad/s, and rev/min are given as vibration.rpm" if self.only_speed \
            else ""
        asked = millimetres_question(some=any(item.kind in SOME_IN_MILLIMETRES for item in self.found),
                                     second_moment=any(item.kind == "second_moment" for item in self.found))
        return "; ".join(item.detail for item in self.found) + f": {asked}{unless}"


__all__ = ["FASTEST_BASE_M_S", "FLATTEST_ROTOR", "GRAMS_PER_KILOGRAM", "LARGEST_RADIUS_M", "LARGEST_SECOND_MOMENT_M4",
           "LIGHTEST_AT_ONE_METRE", "LIGHTNESS_EXPONENT", "LONGEST_ROTOR_M", "MIXED_RATIO", "ROTOR_REACH",
           "SOME_IN_MILLIMETRES", "THICKEST_SHAFT_M", "THINNEST_DISC", "Implausible",
           "LengthsInMillimetres", "bounding_cylinder", "heaviest_rotor", "lightest_rotor", "radii_are_eccentricities",
           "rotor_length", "solid_steel_reach"]
