"""Readings off the plans and the table of their errors against the analytic solution.

A reading is a length of the drawing, in mm, between two plan points (``pb``,
``ab``, ``n3b``), turned into a quantity by the scale and, for ω and ε, by a
link's length: ``VB = pb·μV``, ``ω3 = ab·μV / lAB``, ``ε3 = n3b·μa / lAB``; a
sliding pair's relative velocity and relative acceleration are read along
its guide (``VBB4 = b4b·μV``, ``aBB4^r = k5b·μa``).
Three sources give the lengths: the plan as constructed, the same plan read
with a ruler to the drafting precision, and the readings a student took off a
hand-drawn plan (the scene's ``[measured]``).  Each quantity is compared with
the exact value: ``δ = (analytic − plan) / analytic · 100 %``.  The force
polygons are read the same way, a reaction as its vector's length times μF,
against the reactions of all equilibrium equations solved at once.
"""

from __future__ import annotations

import math
import re
import unicodedata
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING

from .errors import SceneError
from .forces import ForcePlan
from .kinematics import at
from .locale import load_symbol
from .lookalikes import lookalike_hint, twin
from .mechanism import Mechanism
from .plans import LaidVector, Plan, Step

if TYPE_CHECKING:
    from .motion import Motion

SOURCES = ("construction", "drafting", "measured")


@dataclass(frozen=True)
class SlidingPair:
    """A sliding pair at one instant: link ``slider`` runs at ``joint`` along a line fixed in link ``guide``.

    ``through`` is a point fixed on the guide link (None on the frame) and
    ``arm`` the vector from it to the joint (m), so that the motion of the
    guide link's point under the slider follows from ``through``'s.
    """

    slider: int
    guide: int
    joint: str
    through: str | None = None
    arm: complex = 0j


@dataclass(frozen=True)
class Reading:
    """How one quantity is read off a plan.

    ``segment`` is the pair of plan letters whose distance is measured;
    ``length`` the link length it is divided by (1 for a linear quantity);
    ``sign`` the sense the construction gives it (+1 ccw, −1 cw) for ω and ε,
    and 1 for magnitudes; ``points`` the two mechanism points (B, A) of a
    relative vector vBA; ``slide`` the sliding pair whose relative velocity
    or relative acceleration the segment is.
    """

    quantity: str
    plan: str
    segment: tuple[str, str]
    length: float = 1.0
    sign: float = 1.0
    points: tuple[str, str] | None = None
    slide: SlidingPair | None = None

    def value(self, plans: Mapping[str, Plan], millimetres: float | None = None) -> float:
        """The quantity from the segment's length (``millimetres`` overrides the plan's own)."""
        mm = self.millimetres(plans) if millimetres is None else millimetres
        return self.sign * mm * plans[self.plan].scale / self.length

    def millimetres(self, plans: Mapping[str, Plan]) -> float:
        """The segment's length (mm) on its plan as constructed."""
        return segment_millimetres(plans[self.plan], self.segment)


def segment_millimetres(plan: Plan, segment: tuple[str, str]) -> float:
    """The length (mm) of ``segment``, two of ``plan``'s letters, on the plan as constructed."""
    return abs(plan.mm(segment[1]) - plan.mm(segment[0]))


@dataclass(frozen=True)
class ErrorRow:
    position: int
    quantity: str
    analytic: float
    plan: float
    source: str
    # The hand reading a measured row comes from, as the scene gives it: "pd = 13.86 mm".
    reading: str = ""
    # What a millimetre of that reading's segment stands for (m/s, rad/s, N, ... per mm): a measured row's slack.
    per_millimetre: float = 0.0
    # The label of the force polygon a measured reaction is read off (II(3,4)): each polygon may have a μF of its
    # own, so a polygon drawn at another scale shows as its readings alone in one ratio to the construction.
    polygon: str = ""

    @property
    def percent(self) -> float:
        """(analytic − plan) / analytic · 100; 0 when both are zero."""
        if self.analytic == 0:
            return 0.0 if self.plan == 0 else math.inf
        return (self.analytic - self.plan) / self.analytic * 100.0


def readings(mechanism: Mechanism, plans: Mapping[str, Plan], positions: Mapping[str, complex]) -> list[Reading]:
    """Every quantity the plans give, in textbook order: absolute, relative, sliding, then angular.

    ``plans`` has the velocity plan and, where one was drawn, the acceleration plan.
    """
    result: list[Reading] = []
    frame = set(mechanism.scene.frame_points)
    for kind, symbol in (("velocity", "V"), ("acceleration", "a")):
        if kind not in plans:
            continue
        plan = plans[kind]
        moving = [name for name in plan.images if name not in frame and name in positions]
        result += [Reading(f"{symbol}{name}", kind, ("p", plan.images[name])) for name in moving]
        for name, first, second in _relative_pairs(mechanism, plans["velocity"]):
            result.append(Reading(f"{symbol}{name}", kind, (plan.images[first], plan.images[second]),
                                  points=(second, first)))
        for sliding in _sliding_readings(mechanism, plan, symbol, positions):
            # An RPR's sliding velocity is also the relative velocity of two named points (vA4A3).
            same = [k for k, reading in enumerate(result) if reading.quantity == sliding.quantity]
            if same:
                result[same[0]] = replace(result[same[0]], slide=sliding.slide)
            else:
                result.append(sliding)
        for link in mechanism.moving_links:
            if link in mechanism.translating:  # never turns: an ω or ε row would only show zeros
                continue
            reading = _angular(mechanism, plans, kind, link, positions)
            if reading is not None:
                result.append(reading)
    return result


def _relative_pairs(mechanism: Mechanism, velocity: Plan) -> list[tuple[str, str, str]]:
    """(name, A, B) for every relative velocity vBA the velocity plan laid off between two images.

    ``name`` is the vector's own name (``BA``, or ``A4A3`` for a block sliding
    on a lever, whose two points share a position); A and B are the points
    whose images it joins.
    """
    names: dict[str, str] = {}
    for name, letter in velocity.images.items():
        names.setdefault(letter, name)
    pairs = []
    for step in velocity.steps:
        for vector in step.vectors:
            if not vector.meaning.startswith("v") or vector.end == "p" or vector.end not in names:
                continue
            moving = names[vector.end]
            about = vector.meaning[1 + len(moving):] if vector.meaning[1:].startswith(moving) else ""
            if not (about in velocity.images and velocity.images[about] == vector.start):
                # the pole stands for every frame point, so only a name can say which one
                about = names.get(vector.start) if vector.start != "p" else None
            if about and about != moving:
                pair = (vector.meaning[1:], about, moving)
                if pair not in pairs:
                    pairs.append(pair)
    return pairs


def sliding_pairs(mechanism: Mechanism, positions: Mapping[str, complex]) -> list[SlidingPair]:
    """The sliding pairs of the groups at the instant whose points are at ``positions``.

    They are the pairs of ``Motion.slides``, in the same order, as each group
    names them (``Group.sliding_pairs``).  The driver's own slide is given,
    not constructed, so it is not among them.
    """
    frame = mechanism.scene.frame_link
    pairs = []
    for slider, guide, joint in (pair for group in mechanism.groups for pair in group.sliding_pairs(mechanism)):
        if guide == frame:
            pairs.append(SlidingPair(slider, guide, joint))
            continue
        through = min(name for name in mechanism.fixed_on[guide] if name in positions and name != joint)
        pairs.append(SlidingPair(slider, guide, joint, through, positions[joint] - positions[through]))
    return pairs


def _sliding_readings(mechanism: Mechanism, plan: Plan, symbol: str,
                      positions: Mapping[str, complex]) -> list[Reading]:
    """The relative velocity (or relative acceleration ``^r``) of every sliding pair, read along its guide.

    The segment is the vector the group laid off along the guide, between
    the letters it recorded for the slide (``Plan.slide_ends``); the
    quantity is named as the step's equation names that vector.
    """
    result = []
    for pair in sliding_pairs(mechanism, positions):
        if pair.slider not in plan.slide_ends:
            continue
        laid = _laid_along_guide(plan, plan.slide_ends[pair.slider])
        if laid is None:
            continue
        step, vector = laid
        quantity = symbol + _sliding_name(step, vector, pair)[1:]
        result.append(Reading(quantity, plan.kind, (vector.start, vector.end), slide=pair))
    return result


def _laid_along_guide(plan: Plan, ends: tuple[str, str]) -> tuple[Step, LaidVector] | None:
    """The vector a step laid off along a guide (a line of action ``∥ …`` from its start to the crossing it fixed)
    between the slide's two letters, either way round; or, where the slider's pin was put on the plan by
    similarity (a triad's sliding leg whose normal runs through Assur's point), the vector a step that fixes
    nothing read off between them.

    Asked by its letters, not its value: at an extreme two slides may both be
    zero, and a normal or tangential component zero at this instant would
    equal either.
    """
    for step in plan.steps:
        along = {line.through for line in step.lines if line.along.parallel}
        for vector in step.vectors:
            if vector.start == vector.end or {vector.start, vector.end} != set(ends):
                continue
            if (vector.start in along and vector.end in step.fixes) or not step.fixes:
                return step, vector
    return None


def _sliding_name(step: Step, vector: LaidVector, pair: SlidingPair) -> str:
    """``vBB4``, ``aA4A3^r``: the vector's own name, or, when it is laid from the pole, the equation's.

    On a frame guide the sliding vector starts at the pole, where it is also
    the absolute vector (``vB``); the equation writes it as relative to the
    frame's point under the slider (``vB = … = vB1 + vBB1``).  A vector from
    the pole already named as relative, of two points at the joint, keeps its
    name: a block pinned to the frame in a slot of a moving link (``vE6E``),
    an RPR's block pivoted on a frame point P, whose P3 is at the pole
    (``vP4P3``).
    """
    named = vector.meaning.removesuffix("^r")[1:]
    at_joint = rf"{re.escape(pair.joint)}\d*"
    if vector.start != "p" or re.fullmatch(at_joint * 2, named):
        return vector.meaning
    for term in re.split(r"\s*[=+]\s*", step.equation):
        rest = term[len(vector.meaning):].removesuffix("^r")
        if term.startswith(vector.meaning) and rest.rstrip("0123456789") and rest.endswith(str(pair.guide)):
            return term
    return f"{vector.meaning}{pair.joint}{pair.guide}"


def _angular(mechanism: Mechanism, plans: Mapping[str, Plan], kind: str, link: int,
             positions: Mapping[str, complex]) -> Reading | None:
    """ω or ε of ``link`` from a relative vector of two of its points, as the textbook reads it.

    ω from the relative velocity of the link's two points farthest apart;
    ε from a tangential component the acceleration plan laid off on the link
    (``n3b`` for ``aBA^τ``), divided by the length between its points.
    """
    plan = plans[kind]
    members = plan.members.get(link, ())
    sign = 1.0 if plan.rates[link] >= 0 else -1.0
    if kind == "velocity":
        pairs = [(a, b) for i, a in enumerate(members) for b in members[i + 1:] if a[0] != b[0]]
        if not pairs:
            return None
        (first, first_letter), (second, second_letter) = max(pairs, key=lambda ab: abs(ab[0][0] - ab[1][0]))
        return Reading(f"omega{link}", kind, (first_letter, second_letter), abs(second - first), sign)
    named = {name: positions[name] for name in plan.images
             if name in positions and (positions[name], plan.images[name]) in members}
    # A construction point of the link that the scene does not name (Assur's special point Σ6) may end the
    # tangential part that gives ε (aFΣ6^τ).
    on_link = {position for position, _ in members}
    named.update({name: where for name, where in plan.auxiliary.items() if where in on_link})
    for step in plan.steps:
        for vector in step.vectors:
            if not vector.meaning.endswith("^τ"):
                continue
            pair = _point_pair(vector.meaning[1:-2], list(named))
            if pair is not None and named[pair[0]] != named[pair[1]]:
                return Reading(f"epsilon{link}", kind, (vector.start, vector.end),
                               abs(named[pair[0]] - named[pair[1]]), sign)
    return None


def _point_pair(text: str, names: list[str]) -> tuple[str, str] | None:
    """``"BA"`` → ``("B", "A")`` when both are among ``names`` (longest names tried first)."""
    for first in sorted(names, key=len, reverse=True):
        if text.startswith(first) and text[len(first):] in names:
            return first, text[len(first):]
    return None


def epsilon_of_another(plans: Mapping[str, Plan], table: Iterable[Reading]) -> dict[int, int]:
    """The links whose ε is another link's reading: ``{3: 4}`` where link 3 turns with link 4 and has no ε of its own.

    A link that turns with another (an RPR's block carrying a point of its rod, ``ae = pa4·lAE/lCA4`` turned as
    pa4 is) has its ω read off its own two images, ``ae`` being square to AE on the velocity plan; on the
    acceleration plan its image is laid off similar to the other link's, with no tangential component of its own
    to read, so its ε is the other's by the kinematics alone (``ε3 = ε4``), followed to the link whose ε is read.
    """
    if "acceleration" not in plans:
        return {}
    read = {reading.quantity for reading in table}
    turns_with = {step.similarity.link: step.similarity.turns_with for step in plans["acceleration"].steps
                  if step.similarity is not None and step.similarity.turns_with is not None}
    found = {}
    for link, other in turns_with.items():
        if f"epsilon{link}" in read:
            continue
        seen = {link}
        while f"epsilon{other}" not in read and other in turns_with and other not in seen:
            seen.add(other)
            other = turns_with[other]
        if f"epsilon{other}" in read:
            found[link] = other
    return found


def drafted(millimetres: float, precision: float) -> float:
    """A length as a person reads it with a ruler: rounded to the drafting precision."""
    return round(millimetres / precision) * precision


def error_rows(position: int, analytic: Mapping[str, float], plans: Mapping[str, Plan], table: list[Reading],
               precision: float, measured: Mapping[str, Mapping[str, float]] | None = None) -> list[ErrorRow]:
    """The error table of one position: every reading against the analytic value, per source.

    A quantity that vanishes at the position (a block at rest in its slot at
    a dead point) is zero in both solutions up to rounding; its two
    roundings would give a meaningless percentage, so both are written as 0.
    """
    rows = []
    exact_values = dict(analytic)
    for reading in table:
        exact, constructed = analytic[reading.quantity], reading.value(plans)
        if _vanishes(reading, plans, exact):
            exact = constructed = exact_values[reading.quantity] = 0.0
        rows.append(ErrorRow(position, reading.quantity, exact, constructed, "construction"))
        rows.append(ErrorRow(position, reading.quantity, exact,
                             reading.value(plans, drafted(reading.millimetres(plans), precision)), "drafting"))
    if measured:
        rows += _measured_rows(position, exact_values, plans, table, measured)
    return rows


# Below this share of its plan's size a segment, and the analytic value it stands for, are rounding.
NEGLIGIBLE = 1e-9


def is_reaction(quantity: str) -> bool:
    """Whether an error row's quantity is a reaction of the force polygons (``R23``), not a plan's value."""
    return quantity.startswith("R") and quantity[1:].isdigit()


# The balancing load's quantity in the error table: the moment on a driving crank (N·m), the force on a slider (N).
BALANCING = ("Mb", "Fb")


def is_balancing(quantity: str) -> bool:
    """Whether an error row's quantity is the balancing load (``Mb``, ``Fb``), a value found by hand, not a length."""
    return quantity in BALANCING


def balancing_error_rows(position: int, exact: float, forces: ForcePlan, symbol: str, unit: str,
                         measured: float) -> list[ErrorRow]:
    """The balancing load a student found by hand (``[measured.N] balancing``: Mb = R32·h, or off Zhukovsky's
    lever) against the linear system's ``exact`` one, beside the force analysis's own (the crank's moment equation,
    the slider's polygon).  The student gives its size; its sense is taken from the force analysis, as a plan
    reading's ω takes the plan's, so the rows are signed as the exact value is (ccw, or along the guide, positive).
    A value, not a length: no drafting row, and nothing a millimetre stands for."""
    sense = -1.0 if (forces.balancing or exact) < 0 else 1.0
    return [ErrorRow(position, symbol, exact, forces.balancing, "construction"),
            ErrorRow(position, symbol, exact, sense * measured, "measured", f"balancing = {measured:g} {unit}")]


def force_error_rows(position: int, exact: Mapping[str, complex], forces: ForcePlan, precision: float,
                     measured: Mapping[str, float] | None = None) -> list[ErrorRow]:
    """The reactions of the force polygons against the linear system's ``exact`` ones, per source.

    A reaction is read off its polygon as the length of its vector times μF,
    so a student's readings (``measured``, mm) are taken at the polygons'
    own μF.  A reaction that vanishes at the position is zero in both
    solutions up to rounding and is written as 0 in both, as a plan's
    vanishing quantity is.
    """
    largest = max((abs(force) for force in exact.values()), default=0.0)
    vanished = {name for name, found in forces.reactions.items()
                if max(abs(found.force), abs(exact[name])) <= NEGLIGIBLE * largest}
    analytic = {name: 0.0 if name in vanished else abs(exact[name]) for name in forces.reactions}
    rows = []
    for name, found in forces.reactions.items():
        constructed = 0.0 if name in vanished else abs(found.force)
        rows.append(ErrorRow(position, name, analytic[name], constructed, "construction"))
        scale = forces.scale_of(name)
        rows.append(ErrorRow(position, name, analytic[name], drafted(constructed / scale, precision) * scale,
                             "drafting"))
    read: dict[str, str] = {}
    for name, millimetres in (measured or {}).items():
        where = f"measured.{position}.forces.{name}"
        reaction, polygon, scale = _measured_reaction(forces, name, where)
        if reaction in read:
            raise SceneError(where, f"measures the reaction {read[reaction]} measures (one is the other reversed): "
                             "give each reaction once")
        read[reaction] = name
        rows.append(ErrorRow(position, reaction, analytic[reaction], millimetres * scale, "measured",
                             f"{name} = {millimetres:g} mm at μF = {scale:g} N/mm", scale, polygon))
    return rows


def _measured_reaction(forces: ForcePlan, name: str, where: str) -> tuple[str, str, float]:
    """The reaction a hand reading ``name`` measures, the label of the polygon it was read on and its μF.

    A polygon draws a reaction under the name of the link it acts on: group II(3,4) closes with R43 (link 4
    on 3, −R34), the crank's polygon lays off R32 (−R23, found by the group before).  Such a reading is of
    the reaction the other way round, at the μF of the polygon that draws it.
    """
    if name in forces.reactions:
        finds = next((group for group in forces.groups if any(found.name == name for found in group.found)), None)
        return name, finds.label if finds else "", forces.scale_of(name)
    opposite = next((found for found in forces.reactions.values() if f"R{found.target}{found.source}" == name), None)
    if opposite is None:
        component = _component_of(forces, name)
        if component is not None:
            raise SceneError(where, f"{component}; the polygons find {', '.join(forces.reactions)}")
        # Mb, Fb, or the Russian Му (уравновешивающий) in either alphabet.
        if name.lower() in ("mb", "fb", "mу", "му", "fу"):
            raise SceneError(where, f"{name} is the balancing load, a value, not a reaction's length on a polygon: "
                             f"give it as [measured.{where.split('.')[1]}] balancing = … (N·m for a crank's moment, "
                             f"N for a slider's force); the polygons have {', '.join(forces.reactions)}")
        raise SceneError(where, f"the force polygons have no reaction {name}; they have {', '.join(forces.reactions)}"
                         f"{_lettering_hint(name, [], _reaction_names(forces))}")
    drawn = next((group for group in forces.groups if any(vector.name == name for vector in group.polygon.vectors)),
                 None)
    if drawn is None:
        return opposite.name, "", forces.scale_of(opposite.name)
    return opposite.name, drawn.label, drawn.scale


# A reaction's normal or tangential component as a polygon letters it (R23n, R23τ) or a student types it (R23t).
_COMPONENT = re.compile(r"^(R\d+)\^?(n|ⁿ|τ|t)$")


def _component_of(forces: ForcePlan, name: str) -> str | None:
    """What a reading named as a reaction's component (``R23n``, ``R14τ``) is, and what to give instead.

    A polygon lays the components off to find the whole reaction (the tangential one from a moment equation,
    the normal one by closing the polygon); the error table compares whole reactions with the linear system's,
    and the polygon letters the whole one too, so that one is read.
    """
    matched = _COMPONENT.match(name)
    if matched is None:
        return None
    whole, part = matched[1], "normal" if matched[2] in "nⁿ" else "tangential"
    # The reaction either way round (R32 is R23 on the crank's polygon), as a reading of the whole one is taken.
    same = {pair for found in forces.reactions.values()
            for pair in ((found.name, f"R{found.target}{found.source}"), (f"R{found.target}{found.source}", found.name))
            if pair[0] == whole}
    if not same:
        return None
    names = {each for pair in same for each in pair}
    drawn = next(((group.label, component[1]) for group in forces.groups for vector in group.polygon.vectors
                  if (component := _COMPONENT.match(vector.name)) and component[1] in names), None)
    if drawn is None:
        return f"{name} would be a component of {whole}, which no polygon lays off in components: give {whole} whole"
    label, lettered = drawn
    return (f"{name} is the {part} component of {whole} on the polygon of {label}, laid off to find it and not "
            f"checked: give the whole reaction {lettered} (lettered on that polygon beside its components)")


def _vanishes(reading: Reading, plans: Mapping[str, Plan], exact: float) -> bool:
    """Whether the plan's segment and the analytic value are both below :data:`NEGLIGIBLE` of the plan's size."""
    plan = plans[reading.plan]
    size_mm = max(abs(plan.mm(letter)) for letter in plan.points)
    exact_mm = abs(exact) * reading.length / plan.scale
    return max(reading.millimetres(plans), exact_mm) <= NEGLIGIBLE * size_mm


def _measured_rows(position, analytic, plans, table, measured) -> list[ErrorRow]:
    """Rows for the scene's hand readings: each segment gives every quantity read from that segment."""
    rows = []
    for kind, lengths in measured.items():
        letters = sorted(plans[kind].points, key=len, reverse=True)
        read: dict[frozenset[str], str] = {}
        for segment_name, millimetres in lengths.items():
            where = f"measured.{position}.{kind}.{segment_name}"
            # The acceleration plan's pole is drawn π and named p; a reading may call it either.
            written = segment_name.replace("π", "p") if kind == "acceleration" else segment_name
            try:
                segment = split_segment(written, letters, where)
            except SceneError:
                _refuse_a_value(segment_name, table, where)
                raise
            if frozenset(segment) in read:
                raise SceneError(where, f"is the segment {read[frozenset(segment)]} again (the same two points): "
                                 "measure each segment once")
            read[frozenset(segment)] = segment_name
            matches = [r for r in table if r.plan == kind and set(r.segment) == set(segment)]
            if not matches:
                readable = dict.fromkeys("".join(r.segment) for r in table if r.plan == kind)
                raise SceneError(where, f"the plan has no quantity read from {segment[0]}{segment[1]}"
                                 f"{_laid_off(plans[kind], segment)}; its quantities are read from {', '.join(readable)}")
            for reading in matches:
                rows.append(ErrorRow(position, reading.quantity, analytic[reading.quantity],
                                     reading.value(plans, millimetres), "measured", f"{segment_name} = {millimetres:g} mm",
                                     abs(reading.value(plans, 1.0))))
    return rows


def _laid_off(plan: Plan, segment: tuple[str, str]) -> str:
    """Why a segment the plan letters gives nothing to check: the Coriolis and normal components are laid off
    from a computed value (2·ω·v, ω²·l), not found by the construction, so a reading of them checks the
    arithmetic, not the drawing; the tangential part beside a normal one gives ε (the table's list says which)."""
    written = f"{segment[0]}{segment[1]}"
    # The Coriolis vector is laid off from 2·ω·v, not found by the construction: nothing to read.
    coriolis = _coriolis_vectors(plan)
    if set(segment) in [set(ends) for ends in coriolis]:
        return f" ({written} is the Coriolis component, laid off from 2·ω·v, not read off)"
    # A segment that only ends where the Coriolis vector does (pk) is no vector of the plan: calling it the
    # Coriolis component would send the student to the wrong segment.
    ending = next((ends for ends in coriolis if ends[1] in segment), None)
    if ending is not None:
        return (f" ({written} is no vector of the plan: {ending[1]} ends the Coriolis component {''.join(ending)}, "
                "laid off from 2·ω·v, not read off)")
    normal = next((vector.meaning for step in plan.steps for vector in step.vectors
                   if vector.meaning.endswith("ⁿ") and {vector.start, vector.end} == set(segment)), None)
    if normal is not None:
        return (f" ({written} is the normal component {normal}, laid off from ω²·l = v²/l, not read off: "
                "the tangential component beside it gives ε)")
    return ""


# A quantity's key (results.json's, the scene's) spells the Greek letter out; the tables, the note and the console
# write the letter.
_GREEK = {"omega": "ω", "epsilon": "ε"}
# How a student may type a value's name: the table's own (VE, omega4) or the textbook's letters (ω4, ε3).
_GREEK_NAMES = {letter: word for word, letter in _GREEK.items()}


def quantity_symbol(quantity: str, text: Mapping[str, str] | None = None) -> str:
    """A quantity as the textbook writes it, for a person to read: ``omega3`` → ``ω3``, ``VB`` unchanged; given the
    locale's ``text``, the balancing load as it writes it (``Mb`` → ``Mу``), the console's English without it."""
    if text is not None and is_balancing(quantity):
        return load_symbol(quantity, text)
    for word, letter in _GREEK.items():
        if quantity.startswith(word) and quantity[len(word):].isdigit():
            return letter + quantity[len(word):]
    if quantity.endswith("^r"):
        # The relative acceleration as the note and the plans letter it (aBB4ʳ), not a caret Markdown shows as typed.
        return quantity.removesuffix("^r") + "ʳ"
    return quantity


def _refuse_a_value(name: str, table: list[Reading], where: str) -> None:
    """Refuse a reading named as the value it stands for (``VE = 0.758``, ``omega4``), not as its segment: the
    hint names the segment to measure instead, on the plan that gives the value (a student's common slip)."""
    quantity = next((f"{word}{name[len(letter):]}" for letter, word in _GREEK_NAMES.items() if name.startswith(letter)),
                    name)
    reading = next((reading for reading in table if reading.quantity == quantity), None)
    if reading is None:
        return
    segment = "".join(reading.segment)
    plan = where.split(".")[2] if where.count(".") >= 3 else reading.plan
    under = "" if plan == reading.plan else f" under [measured.{where.split('.')[1]}] {reading.plan}"
    raise SceneError(where, f"{name} is the value, not a segment: give the segment {segment}{under} it is read from, "
                     f"its length on the {reading.plan} plan in mm")


def _coriolis_vectors(plan: Plan) -> list[tuple[str, str]]:
    """The (start, end) letters of the plan's Coriolis components (``a``, ``k``); a point named K has the image k."""
    return [(vector.start, vector.end) for step in plan.steps for vector in step.vectors
            if vector.meaning.endswith("ᵏ")]


def split_segment(name: str, letters: list[str], where: str) -> tuple[str, str]:
    """``"n3b"`` → ``("n3", "b")``: the two plan letters a segment's name joins."""
    for first in letters:
        if name.startswith(first) and name[len(first):] in letters:
            return (first, name[len(first):])
    kind = where.split(".")[2:3]
    listed = ", ".join(sorted(letters))
    hint = _lettering_hint(name, letters, [a + b for a in letters for b in letters if a != b])
    # Its first letter the plan's, the rest none: the rest is what to look at (px, ak on a plan with no k), not
    # the pole or the case of letters that are right.
    first = next((letter for letter in letters if name.startswith(letter)), None)
    if first is not None and not hint:
        typed = where.rsplit(".", 1)[-1]
        shown = "π (p)" if first == "p" and typed.startswith("π") else first  # the pole as the reading wrote it
        raise SceneError(where, f"is no segment of the plan: {shown} is one of its letters, {name[len(first):]} is "
                         f"none ({listed})")
    pole = " (its pole π is p)" if "p" in letters and kind == ["acceleration"] else ""
    if kind == ["velocity"] and "π" in name:
        pole = " (π is the acceleration plan's pole; the velocity plan's is p)"
    raise SceneError(where, f"is not two letters of the plan ({listed}){pole}{hint}")


def _reaction_names(forces: ForcePlan) -> list[str]:
    """Every name a reading of the polygons may give: each reaction, and each the other way round."""
    return [name for found in forces.reactions.values()
            for name in (f"R{found.source}{found.target}", f"R{found.target}{found.source}")]


def _lettering_hint(name: str, letters: list[str], names: list[str]) -> str:
    """Why a name a student typed is none of ``names``, a plan's segments or a polygon's reactions: one of them
    that looks the same in other letters (a Cyrillic р for the Latin p, or the Latin a where the plan's letters
    are Cyrillic), another Cyrillic letter, or capitals where the plan's letters are small."""
    if twin(name, names) is not None:
        return lookalike_hint(name, names)
    cyrillic = [letter for letter in dict.fromkeys(name) if unicodedata.name(letter, "").startswith("CYRILLIC")]
    if cyrillic:
        written = ", ".join(f"'{letter}' (U+{ord(letter):04X})" for letter in cyrillic)
        return f"; it has the Cyrillic letter{'s' if len(cyrillic) > 1 else ''} {written}: type the Latin one"
    if name != name.lower() and name.lower() in names:
        return f"; the plan's letters are small: write {name.lower()}"
    # 机械原理 letters the acceleration plan p′, b′; an input method types ｐｂ in full width.
    plain = unicodedata.normalize("NFKC", name).translate(_PRIMES)
    if plain != name:
        why = "the plans' letters take no prime" if any(prime in name for prime in _PRIME_MARKS) else \
            "it has full-width letters"
        if any(plain.startswith(letter) and plain[len(letter):] in letters for letter in letters):
            return f"; {why}: write {plain}"
    return ""


_PRIME_MARKS = "′″'’`"
_PRIMES = str.maketrans("", "", _PRIME_MARKS)


_QUANTITY = re.compile(r"^(V|a|omega|epsilon)(.*)$")


def analytic_values(mechanism: Mechanism, table: list[Reading], velocities: Mapping[str, complex],
                    accelerations: Mapping[str, complex], omega: Mapping[int, float],
                    epsilon: Mapping[int, float]) -> dict[str, float]:
    """The exact value of every quantity of ``table``: magnitudes, and signed ω, ε."""
    values: dict[str, float] = {}
    for reading in table:
        kind, rest = _QUANTITY.match(reading.quantity).groups()  # type: ignore[union-attr]
        if reading.slide is not None:
            relative = _relative_motion(reading.slide, velocities, accelerations, omega, epsilon)
            values[reading.quantity] = abs(relative[0] if kind == "V" else relative[1])
        elif kind == "omega":
            values[reading.quantity] = omega[int(rest)]
        elif kind == "epsilon":
            values[reading.quantity] = epsilon[int(rest)]
        else:
            source = velocities if kind == "V" else accelerations
            if reading.points is not None:
                values[reading.quantity] = abs(source[reading.points[0]] - source[reading.points[1]])
            else:
                values[reading.quantity] = abs(source[rest])
    return values


def exact_values_at(mechanism: Mechanism, motion: Motion, table: list[Reading], index: int) -> dict[str, float]:
    """The analytic value at position ``index`` of ``motion`` of every quantity ``table`` reads off the plans."""
    return analytic_values(
        mechanism, table,
        {name: complex(at(p.v, index)) for name, p in motion.points.items()},
        {name: complex(at(p.a, index)) for name, p in motion.points.items()},
        {n: float(at(link.omega, index)) for n, link in motion.links.items()},
        {n: float(at(link.epsilon, index)) for n, link in motion.links.items()})


def _relative_motion(pair: SlidingPair, velocities: Mapping[str, complex], accelerations: Mapping[str, complex],
                     omega: Mapping[int, float], epsilon: Mapping[int, float]) -> tuple[complex, complex]:
    """The slider's velocity ṡ·u and acceleration s̈·u relative to its guide link, from the exact motion.

    With T fixed on the guide link g:  v_rel = vJ − (vT + ωg × TJ),
    a_rel = aJ − (aT + εg × TJ − ωg²·TJ) − 2·ωg × v_rel (the Coriolis part is not relative).
    """
    if pair.through is None:
        return velocities[pair.joint], accelerations[pair.joint]
    spin, whirl = omega[pair.guide], epsilon[pair.guide]
    v_rel = velocities[pair.joint] - velocities[pair.through] - 1j * spin * pair.arm
    a_rel = (accelerations[pair.joint] - accelerations[pair.through] - (1j * whirl - spin * spin) * pair.arm
             - 2j * spin * v_rel)
    return v_rel, a_rel
