"""Units a scene may give that are not SI, as factors to SI; and lengths typed in millimetres where metres are
asked for: how far apart two lengths of one machine stand before one is taken for millimetres, and the question
the warnings then ask; and the question asked of a fraction typed as its percentage."""

from __future__ import annotations

import math

#: rad/s in one revolution per minute.
RPM = math.pi / 30.0
# Standard gravity (m/s²), by which a weight in N is told as the mass in kg it stands for.
STANDARD_GRAVITY = 9.80665
#: No planet's surface pulls harder than Jupiter's 24.8 m/s²; above this the scene's g is Earth's in other units: in
#: ft/s² (32.2), cm/s² (981), mm/s² (9810). Every weight, and every reaction and balancing load with it, would follow.
HEAVIEST_GRAVITY = 30.0
# The other units g is written in, each with its factor to m/s², for the refusal to say which one a value is in.
GRAVITY_UNITS = (("ft/s²", 0.3048), ("cm/s²", 0.01), ("mm/s²", 0.001))


def gravity_unit(value: float) -> str | None:
    """The unit of :data:`GRAVITY_UNITS` in which ``value`` is Earth's g, within 2 %; None where it is in none."""
    for unit, factor in GRAVITY_UNITS:
        if abs(value * factor / STANDARD_GRAVITY - 1.0) < 0.02:
            return unit
    return None


#: Steel's density (kg/m³): a machine's parts are no heavier than solid steel of their size, so a mass beyond that
#: is one typed in grams (a link's, a crank's, a rotor's masses).
STEEL_DENSITY = 7850.0


def solid_steel_cylinder(radius: float, length: float) -> float:
    """The mass (kg) of a solid steel cylinder of ``radius`` and ``length`` (m), the bound a mass typed in grams
    passes where a body of that size could weigh no more."""
    return STEEL_DENSITY * math.pi * radius ** 2 * length

#: A length this many times another of the same machine is one typed in millimetres among metres: a linkage's
#: lengths stand within some 1:50 of each other (a shaper's 0.1 m crank beside its 0.6 m rocker is 1:6), and a
#: rotor's masses turn within as much of the radius their corrections are fixed at.
MIXED_RATIO = 200.0


def percentage_question(value: float, symbol: str) -> str:
    """The question a refusal or a warning asks of a fraction typed as its percentage (δ = 5 for 5 %), with the
    fraction that percentage is.  Its words are the locale's, which the note asks it in too (a damping ratio of 1)."""
    from .locale import strings

    return strings("en")["percentage_question"].format(value=f"{value:g}", symbol=symbol, fraction=f"{value / 100:g}")


def exponent_slip(value: float, smallest: float, largest: float) -> str:
    """The hint of a value a thousand times or more beyond its bounds, which is no machine's but a slip of the
    exponent (1e12 for 12); "" for one nearer, which may be another unit and is told so where it is checked."""
    return "; a slip of the exponent?" if value < smallest / 1000 or value > largest * 1000 else ""


def millimetres_question(*, some: bool = False, second_moment: bool = False) -> str:
    """The question a warning about lengths in millimetres ends with, and the fix: every length divided by 1000
    (and a second moment of area, mm⁴, by 10¹²), or, where only ``some`` are in millimetres among metres, those
    alone (dividing every length would spoil the ones in metres)."""
    if some:
        return "are some lengths in millimetres? The scene's lengths are all in metres (divide millimetres by 1000)"
    also = ", a second moment of area by 10¹²" if second_moment else ""
    return f"are the lengths in millimetres? The scene's lengths are in metres (divide them by 1000{also})"


#: The mains frequencies (Hz) induction motors are built for: their synchronous speeds are 60·f/p rev/min.
MAINS_FREQUENCIES = (50, 60)
#: The most pole pairs of the induction motors a machine is driven by (16 poles: 375 rev/min at 50 Hz); below the
#: synchronous speeds of these the 60·f/p lie so close together that every speed is near one.
MOST_POLE_PAIRS = 8


def synchronous_speeds_rpm(most_pole_pairs: int = MOST_POLE_PAIRS) -> tuple[float, ...]:
    """The synchronous speeds 60·f/p (rev/min) of 50 and 60 Hz induction motors of up to ``most_pole_pairs`` pairs of
    poles, fastest first (3600, 3000, 1800, 1500, …)."""
    speeds = {60.0 * frequency / pairs for frequency in MAINS_FREQUENCIES for pairs in range(1, most_pole_pairs + 1)}
    return tuple(sorted(speeds, reverse=True))


#: The synchronous speeds (rev/min) of the induction motors most machines are driven by, at 50 Hz (3000/p) and
#: 60 Hz (3600/p) down to 720; a motor's nameplate speed lies a few per cent of slip below one (1450 under 1500, 960
#: under 1000).
MOTOR_SYNCHRONOUS_RPM = tuple(speed for speed in synchronous_speeds_rpm(5) if speed >= 720)
#: The most a nameplate speed lies below its synchronous speed: small motors slip 5–8 %.
MOST_MOTOR_SLIP = 0.1
#: How near (relative) a motor's synchronous speed must come to a 60·f/p to be one: 428.6 for 3000/7 is.
SYNCHRONOUS_TOLERANCE = 0.002


def nearest_synchronous_rpm(rpm: float) -> float | None:
    """The synchronous speed 60·f/p (:func:`synchronous_speeds_rpm`) nearest ``rpm``, where ``rpm`` is given as a
    motor's synchronous speed but is none (1500 for 1450, a nameplate's speed typed for it); None where it is one,
    or lies below the slowest (where the 60·f/p crowd together)."""
    speeds = synchronous_speeds_rpm()
    if rpm < (1.0 - MOST_MOTOR_SLIP) * speeds[-1]:
        return None
    nearest = min(speeds, key=lambda speed: abs(rpm / speed - 1.0))
    return None if abs(rpm / nearest - 1.0) <= SYNCHRONOUS_TOLERANCE else nearest


def motor_speed_in_rpm(omega: float) -> bool:
    """Whether ``omega`` (rad/s, as typed) reads as a motor's speed in rev/min: a whole multiple of 5 within
    :data:`MOST_MOTOR_SLIP` below one of :data:`MOTOR_SYNCHRONOUS_RPM` (1450, 2900, 960).  As rad/s these are 6200
    rev/min and more, beyond a course's linkages (an engine's crank turns at 2000–6000 rev/min) and the flywheel
    shafts and machines on mounts the course works out, while a speed given as rpm converts to no such whole
    number."""
    size = abs(omega)
    if size != round(size) or round(size) % 5:
        return False
    return any((1.0 - MOST_MOTOR_SLIP) * synchronous <= size <= synchronous for synchronous in MOTOR_SYNCHRONOUS_RPM)


def rpm_question(key: str, omega: float, rpm_key: str) -> str:
    """The warning of a speed ``key = omega`` that reads as rev/min typed for rad/s, with what it is as rad/s and
    what it would be as rev/min, and the key that takes rev/min; the two written as the note's caution writes them
    (1450 rpm is 151.84 rad/s, where the console's 151.8 stood beside the note's 151.84)."""
    # Here, not above: numerals brings numpy (by rounding), which this module of constants does without.
    from .render.numerals import number

    return (f"{key} = {omega:g} rad/s is {number(abs(omega) / RPM)} rpm: a motor's speed in rev/min typed for rad/s? "
            f"{abs(omega):g} rpm is {number(abs(omega) * RPM)} rad/s: write {rpm_key} = {omega:g}")
