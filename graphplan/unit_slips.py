"""Values of a linkage typed in another unit than the scene's that still run: a crank's speed in rev/min given as
``omega`` (1450 rad/s for a 1450 rpm motor), a link's mass in grams (a 0.3 m rocker of 300 kg), its moment of
inertia in kg·mm² (a 0.55 m coupler turning about a radius of gyration of 5.5 m), a load in kN (a piston's 4.5 kN
gas force typed 4.5, which its own inertia force dwarfs).  Every result follows them a thousand or ten times off, so
the run warns at its first position, naming the key, its value and what was likely meant, as it warns of lengths in
millimetres (:mod:`graphplan.length_units`).
"""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np

from .loads import motion_state, spring_length
from .mechanism import Mechanism
from .motion import Motion, PositionWarning
from .render.numerals import number as written
from .units import STEEL_DENSITY, motor_speed_in_rpm, rpm_question, solid_steel_cylinder

# A link is a bar between its joints.  A course's links weigh q·l, q some 10–40 kg/m (a 0.3 m rocker 3–12 kg);
# even a solid steel bar as thick and as wide as it is long, or 0.1 m square where it is shorter (78.5 kg/m, twice
# the heaviest q), weighs less than ρ·l·max(l, 0.1 m)² (212 kg for 0.3 m, 3.9 kg for 0.05 m), and the same masses
# typed in grams, a thousand times q·l, pass it.  No link is thicker than THICKEST_SECTION_M, however long: beyond
# it the bar is that square, 7850 kg a metre (the heaviest links, a large press's connecting rod or a pumpjack's
# walking beam, weigh some 1–5 t a metre), which a course's 10 kg a metre in grams passes at every length, where
# the cube of a 2 m link, 62.8 t, let a 20 t link of 10 kg/m in grams by.
THINNEST_SECTION_M = 0.1
THICKEST_SECTION_M = 1.0
# The driving crank may carry a flywheel, a gear, counterweights, an eccentric's sheave or a crankshaft's webs and
# journals, a mass its length does not bound; its inertia J, where given, bounds it instead.  A steel body of mass m
# whose radius of gyration in the plane is k = √(J/m) covers at most 2π·k² of the plane (a disc covers the most for
# its k), so it reaches at least m/(2π·ρ·k²) = m²/(2π·ρ·J) along its axis: 0.05 m for a 400 kg flywheel of J = 60
# kg·m², 0.8 m for 20 kg lumped near the pin of a 0.06 m crank at J = 0.01 (a crankshaft's throws), while 4 kg of a
# 0.175 m crank typed in grams, at its J = 0.0102, would reach 32 km.  A crank heavier than a bar that reaches more
# than LONGEST_CRANK times its length (or 0.1 m) along its axis has its mass in grams.  Without J (a crank turning
# at constant ω needs none) its length bounds it more loosely (:func:`heaviest_crank`).
LONGEST_CRANK = 50.0
# A crank given no J is bounded by the heaviest thing a crank of its length carries but a flywheel (which has a J the
# scene would give): a crankshaft's throw, its webs, counterweights and journals, or an eccentric's sheave.  Their
# counterweights sweep some 1.3–1.5 crank radii out and a throw spans about one cylinder's pitch, some 2 crank radii,
# along the shaft; a solid steel cylinder twice the crank's length in radius and twice it long holds either whole:
# ρ·π·(2·l)²·(2·l) = 8π·ρ·l³, l taken at least THINNEST_SECTION_M as for the bar, so 197 kg for a crank up to 0.1 m,
# 1060 kg at 0.175 m.  A truck engine's throw (some 17 kg at a 0.075 m crank) fills a tenth of it, a course's crank
# of 0.1 m (some 2–4 kg) a hundredth; the same crank typed in grams (2000, 500 for 0.5 kg) passes it.
CRANK_REACH = 2.0
# A link's mass lies between its joints, about its centre: its radius of gyration k = √(J/m) is at most half its
# span (two masses at its ends), a uniform bar's l/√12 = 0.29·l.  A link whose k is more than WIDEST_GYRATION times its
# span would have its mass farther out than its joints reach, as J typed in kg·cm² or kg·mm² makes it (a thousand times
# a 0.55 m coupler's 0.51 kg·m² puts k at 5.5 m); a counterweight on an arm beyond the named points is left room.
WIDEST_GYRATION = 2.0
# The units a J is likely typed in for kg·m², with their factor to kg·m².  A reading is offered where it puts k within
# the link as a link's mass lies: from a twentieth of its span (a mass lumped at its centre) to its span.
INERTIA_UNITS = (("kg·cm²", 1e-4), ("kg·mm²", 1e-6), ("g·cm²", 1e-7), ("g·mm²", 1e-9))
NARROWEST_GYRATION = 0.05


def heaviest_crank(length: float) -> float:
    """The most a driving crank of ``length`` (m) given no inertia weighs, kg: a solid steel cylinder
    :data:`CRANK_REACH` times its length (at least :data:`THINNEST_SECTION_M`) in radius and as many times long,
    which holds a crankshaft's throw with its counterweights or an eccentric's sheave."""
    reach = CRANK_REACH * max(length, THINNEST_SECTION_M)
    return solid_steel_cylinder(reach, reach)


def heaviest_bar(length: float) -> float:
    """The most a link of ``length`` (m) between its joints weighs, kg: a solid steel bar as thick and as wide as it
    is long, but at least :data:`THINNEST_SECTION_M` and at most :data:`THICKEST_SECTION_M` square."""
    return STEEL_DENSITY * length * min(max(length, THINNEST_SECTION_M), THICKEST_SECTION_M) ** 2


# An angle typed in radians where the scene asks degrees is a small angle: 1.5708 for 90°, a guide laid along x where it
# was meant to stand across.  Those within this of a whole number of twelfths of π (15°, the angles a course's
# drawings are laid off at), and no whole degree, are told: no drawing lays a line off at 1.571°.
RADIAN_SLIP = 0.002


def angles_in_radians(mechanism: Mechanism, loads: bool = True) -> tuple[PositionWarning, ...]:
    """An ``angle-in-radians`` warning, at the first position, for each angle of the linkage that reads as typed in
    radians (:data:`RADIAN_SLIP`): a guide's or a frame line's, an RPP's or a triad's slot's, the swing's ends, the
    first position's angle, and with ``loads`` a load's direction (which places nothing: no reason a mechanism cannot
    be assembled)."""
    scene = mechanism.scene
    given = [(f"{guide.where}.angle", math.degrees(guide.angle)) for guide in scene.guides
             if guide.line is None and guide.angle_given]
    # An RPP's slot to its guide: 90° unless given, 1.5708 where typed in radians.
    given += [(f"{group.where}.angle", math.degrees(group.angle)) for group in mechanism.groups if group.kind == "RPP"]
    # A triad's slot to the ternary link's BD: 0° unless given.
    given += [(f"{group.slot(leg).where}.angle", math.degrees(group.leg_slots[leg]))
              for group in mechanism.groups if group.kind == "triad" for leg in group.slotted_legs]
    given += [(f"{load.where}.angle", load.angle_deg) for load in scene.loads if loads and load.angle_deg is not None]
    # A slider driver's run is in metres: only a crank's start and swing are angles.
    driver = mechanism.driver
    if driver.kind == "crank" and not isinstance(scene.positions.start, str):
        given.append(("positions.start", scene.positions.start))
    if driver.kind == "crank" and driver.swing is not None:
        given += [(f"{driver.where}.swing[{k}]", math.degrees(end)) for k, end in enumerate(driver.swing)]
    told = []
    for where, degrees in given:
        twelfths = round(degrees / (math.pi / 12.0))
        # Within a turn either way, as an angle in radians is typed: 47.124° is no 15π.
        if 0 < abs(twelfths) <= 24 and degrees != round(degrees) and \
                abs(degrees - twelfths * math.pi / 12.0) <= RADIAN_SLIP:
            meant = twelfths * 15
            told.append(PositionWarning(0, "angle-in-radians", (
                f"{where} = {degrees:.6g} is {_of_pi(twelfths)} in radians: the scene's angles are in degrees, so it "
                f"is taken as {degrees:.6g}°; give {meant} if {meant}° is meant")))
    return tuple(told)


def _of_pi(twelfths: int) -> str:
    """``twelfths`` twelfths of π written as a fraction of π: π/2, 3π/4, −π."""
    share = Fraction(twelfths, 12)
    top = "" if abs(share.numerator) == 1 else str(abs(share.numerator))
    sign = "−" if share < 0 else ""
    return f"{sign}{top}π" + (f"/{share.denominator}" if share.denominator != 1 else "")


def speed_in_rpm(mechanism: Mechanism) -> tuple[PositionWarning, ...]:
    """A ``speed-in-rpm`` warning, at the first position, where the crank's ``omega`` reads as a motor's speed in
    rev/min (:func:`~graphplan.units.motor_speed_in_rpm`)."""
    driver = mechanism.driver
    if driver.kind != "crank" or driver.rpm is not None or not motor_speed_in_rpm(driver.omega):
        return ()
    return (PositionWarning(0, "speed-in-rpm", rpm_question(f"{driver.where}.omega", driver.omega,
                                                            f"{driver.where}.rpm")),)


# A slider driver's velocity is in m/s: a hydraulic cylinder's rod moves at some 0.05–0.5 m/s, a pneumatic one's at
# up to 1.5–3, the fastest linear drives (an impact cylinder, a linear motor) at some 10 m/s.  The same speeds typed
# in mm/s are 50 and more, and the inertia loads they give grow as its square, a million times over.  A driver faster
# than FASTEST_SLIDER_DRIVE_M_S is told.
FASTEST_SLIDER_DRIVE_M_S = 20.0


def velocity_in_millimetres(mechanism: Mechanism) -> tuple[PositionWarning, ...]:
    """A ``velocity-in-mm`` warning, at the first position, where a slider driver's ``velocity`` is faster than any
    cylinder or linear drive pushes (:data:`FASTEST_SLIDER_DRIVE_M_S`): mm/s typed for m/s, with its ``acceleration``
    (where not 0) likely in mm/s² with it."""
    driver = mechanism.driver
    if not _slider_too_fast(mechanism):
        return ()
    told = (f"{driver.where}.velocity = {driver.velocity:g} m/s drives the slider {driver.joint} faster than any "
            f"cylinder or linear drive pushes (over {FASTEST_SLIDER_DRIVE_M_S:g} m/s; a hydraulic cylinder's rod "
            f"moves at some 0.05–0.5 m/s): mm/s typed for m/s? {driver.velocity:g} mm/s is {driver.where}.velocity = "
            f"{driver.velocity / 1000:g}")
    if driver.acceleration:
        told += (f", and {driver.acceleration:g} mm/s² is {driver.where}.acceleration = "
                 f"{driver.acceleration / 1000:g}")
    return (PositionWarning(0, "velocity-in-mm", told + ": the scene's velocities are in m/s, its accelerations in "
                                                        "m/s²"),)


def velocity_slip_hint(mechanism: Mechanism) -> str | None:
    """The fix a refusal of a plan larger than any paper adds where the slider driver's velocity reads as mm/s
    (:func:`velocity_in_millimetres`): its accelerations then a thousand times the driver's own and its plan as
    many times the pole, whose key alone the refusal would send the student to.  None where it does not."""
    if not _slider_too_fast(mechanism):
        return None
    driver = mechanism.driver
    also = f" and {driver.where}.acceleration = {driver.acceleration / 1000:g}" if driver.acceleration else ""
    return (f"{driver.where}.velocity = {driver.velocity:g} m/s is mm/s typed for m/s: give {driver.where}.velocity = "
            f"{driver.velocity / 1000:g}{also}")


def _slider_too_fast(mechanism: Mechanism) -> bool:
    driver = mechanism.driver
    return driver.kind == "slider" and abs(driver.velocity) > FASTEST_SLIDER_DRIVE_M_S


def masses_in_grams(mechanism: Mechanism, motion: Motion) -> tuple[PositionWarning, ...]:
    """A ``masses-in-grams`` warning, at the first position, naming each link whose mass is more than
    :func:`heaviest_bar` of its span (the largest distance between two of its points), with the mass it would be in
    grams; the driving crank only where its inertia, given, makes it too compact to carry a flywheel or counterweights
    (:data:`LONGEST_CRANK`), or, given none, where it is heavier than :func:`heaviest_crank` too."""
    told = []
    for number, link in sorted(mechanism.scene.links.items()):
        span = _body_span(motion, number)
        if span is None or not link.mass > heaviest_bar(span[0]):
            continue
        length, between, own = span
        if not own:
            # A slider's block is often a mechanism's heaviest link: 50 kg typed in grams passed.  No block
            # outweighs a steel bar as long as the whole mechanism is across.
            told.append(f"{link.where}.mass = {link.mass:g} kg on a slider of a mechanism "
                        f"{written(length, 3)} m across ({between}), heavier than a solid steel bar of that "
                        f"length ({written(heaviest_bar(length), 3)} kg): grams typed for kg? {link.mass:g} g is "
                        f"{link.where}.mass = {link.mass / 1000:g}")
            continue
        why = ""
        if number == mechanism.driver.link:
            depth = _crank_depth(link.mass, link.inertia)
            if depth is None:
                if not link.mass > heaviest_crank(length):
                    continue
                reach = CRANK_REACH * max(length, THINNEST_SECTION_M)
                why = (f", and than a steel cylinder {written(reach, 3)} m in radius and long ({CRANK_REACH:g} × "
                       f"max(l, {THINNEST_SECTION_M:g} m)), which holds a crankshaft's throw with its counterweights "
                       f"({written(heaviest_crank(length), 3)} kg; a flywheel on the crank: give {link.where}.inertia)")
            elif not depth > LONGEST_CRANK * max(length, THINNEST_SECTION_M):
                continue
            else:
                why = (f", and too compact for a flywheel or counterweights: with {link.where}.inertia = "
                       f"{link.inertia:g} kg·m², as steel it would reach {written(depth, 3)} m along its axis")
        told.append(f"{link.where}.mass = {link.mass:g} kg on a link {written(length, 3)} m long ({between}), heavier "
                    f"than a solid steel bar of that length ({written(heaviest_bar(length), 3)} kg){why}: grams typed "
                    f"for kg? {link.mass:g} g is {link.where}.mass = {link.mass / 1000:g}")
    if not told:
        return ()
    return (PositionWarning(0, "masses-in-grams", "; ".join(told) + ": the scene's masses are in kg (divide grams "
                                                                    "by 1000)"),)


def inertia_too_large(mechanism: Mechanism, motion: Motion) -> tuple[PositionWarning, ...]:
    """An ``inertia-too-large`` warning, at the first position, naming each link whose radius of gyration √(J/m) is
    more than :data:`WIDEST_GYRATION` times its span (the largest distance between two of its points), with what its
    J would be in kg·m² as the units it was likely typed in (:data:`INERTIA_UNITS`)."""
    told = []
    driver = mechanism.driver
    for number, link in sorted(mechanism.scene.links.items()):
        if not (link.mass > 0 and link.inertia > 0):
            continue  # no radius of gyration: a J alone (a flywheel's) or no J at all
        if driver.kind == "crank" and number == driver.link:
            # The driving crank may carry a flywheel far wider than the crank is long (a 0.06 m crank with a
            # 400 kg, 60 kg·m² flywheel has k = 0.39 m); masses_in_grams judges its mass against its J instead.
            continue
        # A block that turns with its guide (a slotted lever's) has its J in the results, and none turns about a
        # radius of gyration wider than the mechanism is across.
        span = _body_span(motion, number)
        if span is None:
            continue
        length, between, own = span
        body = "link" if own else "slider of a mechanism"
        gyration = math.sqrt(link.inertia / link.mass)
        if not gyration > WIDEST_GYRATION * length:
            continue
        plausible = [(unit, factor) for unit, factor in INERTIA_UNITS
                     if NARROWEST_GYRATION * length <= gyration * math.sqrt(factor) <= length]
        readings = "; ".join(f"{link.inertia:g} {unit} is {link.where}.inertia = {link.inertia * factor:.3g}"
                             for unit, factor in plausible)
        guess = (f"{' or '.join(unit for unit, _ in plausible)} typed for kg·m²? {readings}" if plausible
                 else "no unit explains it: a mistaken value?")
        told.append(f"{link.where}.inertia = {link.inertia:g} kg·m² with mass = {link.mass:g} kg gives a radius of "
                    f"gyration √(J/m) = {written(gyration, 3)} m, {written(gyration / length, 3)} times the "
                    f"{body} {written(length, 3)} m {'long' if body == 'link' else 'across'} ({between}), where a "
                    f"uniform bar of that length has {written(length / math.sqrt(12.0), 3)} m "
                    f"(J = m·l²/12 = {written(link.mass * length ** 2 / 12.0, 3)} kg·m²): {guess}")
    if not told:
        return ()
    return (PositionWarning(0, "inertia-too-large", "; ".join(told) + ": the scene's moments of inertia are in "
                                                                      "kg·m²"),)


def centres_as_shares(mechanism: Mechanism, motion: Motion) -> tuple[PositionWarning, ...]:
    """A ``centre-as-share`` warning, at the first position, naming each link's centre of mass placed ``at`` a share
    of its line (0 < ``at`` ≤ 1) that puts it past the point it is measured toward and out beyond the link's other
    points, stretching the link's span: a share of the line typed for metres, as ``at = 0.5`` for the middle of a
    0.45 m rod puts its centre 0.05 m past its end.  A link's mass lies about its joints; a counterweight beyond them
    (a crank's, at a negative ``at``) or a centre within the link's reach is not told."""
    scene = mechanism.scene
    named = {point.name: point for point in scene.points}
    told = []
    for number, link in sorted(scene.links.items()):
        spec = named.get(link.centre) if link.mass > 0 and link.centre else None
        if spec is None or spec.link != number or not 0.0 < spec.at <= 1.0:
            continue
        line = abs(complex(*motion.point(spec.toward).r[0]) - complex(*motion.point(spec.start).r[0]))
        if not spec.at > line:
            continue
        body = motion.span(number, leaving_out=(spec.name,))
        stretched = motion.span(number)
        if body is None or stretched is None or not stretched[0] > body[0] * (1 + 1e-9):
            continue
        past = spec.at - line
        segment = f"{spec.start}{spec.toward}"
        told.append(f"{spec.where}.at = {spec.at:g} m puts link {number}'s centre of mass {spec.name} "
                    f"{written(past, 3)} m past {spec.toward}, beyond the link's other points (its span grows from "
                    f"{written(body[0], 3)} m, {body[1]}, to {written(stretched[0], 3)} m): a share of {segment} "
                    f"typed for metres? at is metres from {spec.start}; {spec.at:g} of {segment} "
                    f"({written(line, 4)} m) is {spec.where}.at = {written(spec.at * line, 4)}")
    if not told:
        return ()
    return (PositionWarning(0, "centre-as-share", "; ".join(told)),)


# A force typed in kN, a moment in kN·m, where the scene asks N and N·m: a piston's 4.5 kN gas force typed 4.5.  The
# fixtures' forces are 3 to 17 times the largest of their link's own weight and inertia force, their moments 1.8 to
# 28 times the larger of their link's inertia moment J·ε and its weight's moment m·g·l over its span; a thousandth
# of them is under 4 % of those.  A load under KILO_SLIP of them is told: no mechanism is built to carry a useful
# load that its own link's weight and inertia dwarf twenty times over, and its polygon would draw it as a dot.
KILO_SLIP = 0.05


def loads_in_kilonewtons(mechanism: Mechanism, motion: Motion) -> tuple[PositionWarning, ...]:
    """A ``load-in-kn`` warning, at the first position, naming each force or moment (its ``value``, or its
    ``diagram``'s largest) under :data:`KILO_SLIP` of the largest load its own link carries of itself over the
    positions: for a force, its weight m·g and inertia force m·aS; for a moment, its inertia moment J·ε and its
    weight's moment m·g·l over its span.  A spring's force, which its length sets, and a link with no mass or J to
    judge by are not told."""
    scene = mechanism.scene
    told = []
    for spec in scene.loads:
        link = scene.links.get(spec.link)
        if not spec.value or link is None:  # a spring's, which its length sets, or a load left at 0: no slip of units
            continue
        own = _own_loads(motion, spec.kind == "force", spec.link, link, scene.gravity)
        largest = max((value for _, value, _ in own), default=0.0)
        if not (largest > 0 and abs(spec.value) < KILO_SLIP * largest):
            continue
        unit = "N" if spec.kind == "force" else "N·m"
        key, typed = ((f"{spec.where}.diagram", f"with values up to {spec.value:g} {unit}") if spec.diagram
                      else (f"{spec.where}.value", f"= {spec.value:g} {unit}"))
        meant = "its values × 1000" if spec.diagram else f"{key} = {spec.value * 1000:g}"
        # A thousand times a load that stays under the bound is no load in kN either.
        guess = (f"k{unit} typed for {unit}? {spec.value:g} k{unit} is {meant}"
                 if abs(spec.value) * 1000 >= KILO_SLIP * largest else "no unit explains it: a mistaken value?")
        weight = max((value for name, value, _ in own if name.startswith("its weight")), default=0.0)
        if abs(spec.value) * 1000 < KILO_SLIP * largest and abs(spec.value) >= KILO_SLIP * weight:
            # Only the inertia dwarfs it, a thousand times over, and that grows as the driver's speed squared: a
            # crank's epsilon = 1e9 was told only that the rocker's 1500 N·m was "a mistaken value".
            driver = scene.driver
            speed, rate = ("omega", "epsilon") if driver.kind == "crank" else ("velocity", "acceleration")
            guess += (f"; or {driver.where}.{speed} or {driver.where}.{rate} given too large, which the inertia "
                      "grows with?")
        carried = ", ".join(f"{name} {written(value, 3)} {unit}{why}" for name, value, why in own)
        told.append(f"{key} {typed} is {written(100.0 * abs(spec.value) / largest, 2)} % of the largest load link "
                    f"{spec.link} carries of itself ({carried}): {guess}")
    if not told:
        return ()
    return (PositionWarning(0, "load-in-kn", "; ".join(told) + ": the scene's forces are in N, its moments in N·m"),)


# A coil spring squeezes no shorter than its solid length, some 30–50 % of its free length; an extension spring is
# stretched from about its free length.  A spring shorter than SOLID_SHARE of its free length at every position is
# none that can be built, as a free length typed in millimetres makes it: the 0.43–0.6 m spring of a 0.5 m free
# length typed 500 pushes as if squeezed by 499.5 m, and its k·(L − L0) dwarfs every other load.
SOLID_SHARE = 0.2


def free_lengths_in_millimetres(mechanism: Mechanism, motion: Motion) -> tuple[PositionWarning, ...]:
    """A ``free-length-in-mm`` warning, at the first position, naming each spring shorter at every position than
    :data:`SOLID_SHARE` of its ``free_length``, with the free length it would be in millimetres where that one
    leaves the spring longer than its solid length somewhere."""
    springs = [spec for spec in mechanism.scene.loads if spec.spring]
    state = motion_state(motion) if springs else None
    told = []
    for spec in springs:
        lengths = np.atleast_1d(spring_length(spec, state))
        longest = _largest(lengths)
        if longest is None or not longest < SOLID_SHARE * spec.free_length:
            continue
        shortest = float(np.nanmin(lengths))
        meant = spec.free_length / 1000
        guess = (f"mm typed for m? {spec.free_length:g} mm is {spec.where}.free_length = {meant:g}"
                 if SOLID_SHARE * meant <= longest else "no unit explains it: a mistaken value?")
        told.append(f"{spec.where}.free_length = {spec.free_length:g} m is {written(spec.free_length / longest, 3)} "
                    f"times the longest the spring from {spec.along} to {spec.point} gets ({written(shortest, 3)}–"
                    f"{written(longest, 3)} m over the positions), squeezed far past any spring's solid length (a "
                    f"coil spring's is 30–50 % of its free length): {guess}")
    if not told:
        return ()
    return (PositionWarning(0, "free-length-in-mm", "; ".join(told) + ": the scene's lengths are in metres"),)


def _own_loads(motion: Motion, force: bool, number: int, link, gravity: float) -> list[tuple[str, float, str]]:
    """The loads link ``number`` carries of itself, largest over the positions, each named, with what it is taken
    over: for a ``force``, its weight and inertia force; else its inertia moment and its weight's moment over its
    span."""
    weight = link.mass * gravity
    own = []
    if force:
        if weight > 0:
            own.append(("its weight m·g", weight, ""))
        accelerations = np.hypot(*np.asarray(motion.point(link.centre).a, dtype=float).T) if link.centre else []
        if link.mass > 0 and (largest := _largest(accelerations)) is not None:
            own.append(("its inertia force m·aS up to", link.mass * largest, ""))
        return own
    if link.inertia > 0 and (largest := _largest(np.abs(motion.link(number).epsilon))) is not None:
        own.append(("its inertia moment J·ε up to", link.inertia * largest, ""))
    span = motion.span(number)
    if weight > 0 and span is not None:
        own.append(("its weight's moment m·g·l", weight * span[0],
                    f", l = {written(span[0], 3)} m its span ({span[1]})"))
    return own


def _largest(values) -> float | None:
    """The largest of ``values`` that is a number: a position a singular one leaves without its accelerations has
    none; None where none is."""
    finite = np.asarray(values, dtype=float)[np.isfinite(values)]
    return float(finite.max()) if finite.size else None


def _crank_depth(mass: float, inertia: float) -> float | None:
    """How far along its axis a steel body of ``mass`` (kg) reaches at least, whose moment of inertia about its centre
    is ``inertia`` (kg·m²): m²/(2π·ρ·J), m; None where no inertia is given."""
    if not inertia > 0:
        return None
    return mass ** 2 / (2.0 * math.pi * STEEL_DENSITY * inertia)


def _body_span(motion: Motion, link: int) -> tuple[float, str, bool] | None:
    """``link``'s span (:meth:`Motion.span`) and True, or for a slider's block, which has no span of its own, the whole
    mechanism's at the first position and False: what a link's mass and inertia are weighed against."""
    own = motion.span(link)
    if own is not None:
        return (*own, True)
    whole = motion.span()
    return None if whole is None else (*whole, False)

