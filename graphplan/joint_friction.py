"""Friction in the mechanism's pairs, as loads that depend on the reactions.

A turning pair with a journal of radius r and coefficient f has the friction
circle ρ = f·r (:func:`graphplan.friction.friction_circle_radius`): the total
reaction is tangent to it, on the side that makes its moment about the
joint's centre oppose the relative rotation.  That is the frictionless
reaction R through the centre plus a moment ``−sign(ω_rel)·ρ·|R|``.  A
sliding pair with coefficient f (``f/sin θ`` in a V-guide, see
:func:`graphplan.friction.vee_groove_coefficient`) adds a force ``f'·|N|``
along the slide against the relative velocity.  A pair at rest (an extreme
position) rubs against the relative motion about to begin, the sense of the
relative acceleration, as a resisting load does (:mod:`graphplan.loads`):
the velocity's sign there is rounding's.

Both depend on the reaction they change, so the force analysis with friction
is iterated (:func:`graphplan.statics.equilibrium`,
:func:`graphplan.forces.force_plan`) until the reactions settle.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np

from .errors import SceneError
from .forces import Load
from .kinematics import Scalar, Vector
from .loads import at_rest, sense_of_motion
from .lookalikes import lookalike_hint
from .mechanism import Mechanism
from .motion import Motion, PositionWarning
from .scene import FrictionSpec


@dataclass(frozen=True)
class FrictionPair:
    """A pair with friction: ``reaction`` names its reaction (``R23``: link 2 on link 3).

    ``radius`` is the friction circle's ρ for a turning pair; ``coefficient``
    the reduced coefficient f' of a sliding one.
    """

    spec: FrictionSpec
    reaction: str
    sliding: bool
    joint: str
    source: int
    target: int
    radius: float = 0.0
    coefficient: float = 0.0

    @property
    def in_vee(self) -> bool:
        """Whether the pair slides in a V-guide, its coefficient reduced to f′ = f/sin θ (θ of 90° is a flat guide)."""
        theta = self.spec.groove_half_angle
        return self.sliding and theta is not None and not math.isclose(theta, math.pi / 2)

    @property
    def load_names(self) -> tuple[str, str]:
        """The pair's friction loads: on the target from the source, as the tables letter it (``Ff16``,
        ``Mf12``), and back on the source (``Ff61``)."""
        letters = "Ff" if self.sliding else "Mf"
        return f"{letters}{self.source}{self.target}", f"{letters}{self.target}{self.source}"


def pair_name(pair: FrictionPair, pairs: Sequence[FrictionPair]) -> str:
    """How the drawings and the report name a pair with friction in its ρ or f (ρO, fE, ρ23): by its joint, or by
    its links where another pair with friction shares the joint (a block's slide and its pin, ρ23 and f43)."""
    if sum(other.joint == pair.joint for other in pairs) == 1:
        return pair.joint
    return f"{pair.source}{pair.target}"


def friction_pairs(scene_friction: tuple[FrictionSpec, ...], pairs) -> tuple[FrictionPair, ...]:
    """Each ``[[friction]]`` entry matched with its pair (``statics.pairs``); a mismatch is a scene error."""
    found = []
    given: dict[tuple[str, int, int], str] = {}
    if scene_friction:
        # The classic formulas' module (inclines, threads, clutches and their records) only for a scene with friction.
        from .friction import friction_circle_radius, vee_groove_coefficient
    for spec in scene_friction:
        at_joint = [pair for pair in pairs if pair.joint == spec.joint]
        matching = [pair for pair in at_joint if spec.links is None or set(spec.links) == {pair.source, pair.target}]
        if not at_joint:
            known = ", ".join(f"{p.joint} ({p.source}–{p.target})" for p in pairs)
            joints = [pair.joint for pair in pairs]
            # A joint typed in the other case (b, the plans' letter for B) is a slip, as a group's is (mechanism.py).
            other_case = next((joint for joint in joints if joint.casefold() == spec.joint.casefold()), None)
            hint = lookalike_hint(spec.joint, joints) or (f"; did you mean {other_case!r}?" if other_case else "")
            raise SceneError(f"{spec.where}.joint", f"names no pair of the mechanism; its pairs are {known}", spec.joint,
                             hint=hint)
        if not matching:
            joined = " and ".join(f"{p.source}–{p.target}" for p in at_joint)
            raise SceneError(f"{spec.where}.links", f"joint {spec.joint} joins links {joined}, not these",
                             list(spec.links or ()))
        if len(matching) > 1:
            choices = " or ".join(f"[{p.source}, {p.target}]" for p in matching)
            raise SceneError(f"{spec.where}.links", f"joint {spec.joint} has several pairs: say which with links = {choices}")
        pair = matching[0]
        # A second coefficient for one pair would silently replace the first in the force analysis.
        key = (pair.joint, pair.source, pair.target)
        if key in given:
            raise SceneError(spec.where, f"the pair at {spec.joint} ({pair.source}–{pair.target}) has its friction "
                             f"in {given[key]} already")
        given[key] = spec.where
        if pair.sliding:
            if spec.radius is not None:
                raise SceneError(f"{spec.where}.radius", f"the pair at {spec.joint} slides: a radius is for a turning pair")
            coefficient = spec.f if spec.groove_half_angle is None else vee_groove_coefficient(spec.f, spec.groove_half_angle)
            found.append(FrictionPair(spec, pair.name, True, pair.joint, pair.source, pair.target,
                                      coefficient=float(coefficient)))
        else:
            if spec.radius is None:
                raise SceneError(f"{spec.where}.radius", f"the pair at {spec.joint} turns: give its journal radius (m) "
                                                         "for the friction circle")
            if spec.groove_half_angle is not None:
                raise SceneError(f"{spec.where}.groove_half_angle", f"the pair at {spec.joint} turns: a groove is for a slide")
            found.append(FrictionPair(spec, pair.name, False, pair.joint, pair.source, pair.target,
                                      radius=float(friction_circle_radius(spec.f, spec.radius))))
    return tuple(found)


def check_journals(friction: tuple[FrictionPair, ...], mechanism: Mechanism, motion: Motion) -> None:
    """Refuse a turning pair's journal ``radius`` larger than every link the pair joins (a radius in millimetres
    typed as metres): no pin is wider than the links it is on, and its friction circle ρ = f·r would change every
    reaction, the efficiency and the drawings' scale.  A journal wider than one of its links, an eccentric's sheave
    on its short crank, is built; one wider than all of them is not.

    The friction circle is refused by the same rule: ρ ≤ r while f ≤ 1, so one wider than every link the pair
    joins comes of an f no pair of materials has (a percentage typed for it), and locked a slider-crank at every
    position, each warned of alike, with nothing left to show of the friction."""
    for pair in friction:
        if pair.sliding:
            continue
        spans = [(link, *span) for link in (pair.source, pair.target) if (span := motion.span(link)) is not None]
        if not spans:
            continue
        longest = max(length for _, length, _ in spans)
        if pair.spec.radius <= longest and pair.radius <= longest:
            continue
        radius, f = pair.spec.radius, pair.spec.f
        joined = "; ".join(f"{'the frame' if link == mechanism.scene.frame_link else f'link {link}'} {between}: "
                           f"{length:.4g} m" for link, length, between in spans)
        if radius > longest:
            raise SceneError(f"{pair.spec.where}.radius", (
                f"a journal of radius {radius:g} m at {pair.joint} is larger than the links it joins ({joined}): a "
                f"pin cannot be wider than the links it is on, and its friction circle ρ = {pair.radius:.4g} m would "
                f"change every reaction and the efficiency; the radius is in metres (in millimetres? {radius:g} mm "
                f"is {radius / 1000.0:g} m)"), radius)
        raise SceneError(f"{pair.spec.where}.f", (
            f"makes the friction circle at {pair.joint} ρ = f·r = {f:g} × {radius:g} m = {pair.radius:.4g} m, larger "
            f"than the links the journal joins ({joined}): no pair of materials rubs so hard (f is about 0.1 in a "
            f"journal, rarely above 1 in any pair), and the reactions would pass farther from the pin than the "
            f"links reach; f is a coefficient, not a percentage" +
            (f" ({f:g} % is f = {f / 100.0:g})" if f / 100.0 <= UNUSUAL_F else "")), f)


# Dry steel on steel rubs at 0.15 to 0.8, lubricated pairs at about 0.1: an f above this is a slip (a percentage)
# more often than a material, though clean like metals and rubber do reach it.
UNUSUAL_F = 1.0


def unusual_coefficients(friction: tuple[FrictionPair, ...]) -> tuple[PositionWarning, ...]:
    """A ``high-friction`` warning, at the first position, naming each entry whose f is above :data:`UNUSUAL_F`.

    The f given, not a V-guide's f′ = f/sin θ, which is above f by the groove's wedging alone."""
    told = [f"{pair.spec.where}.f = {pair.spec.f:g} (at {pair.joint})" for pair in friction if pair.spec.f > UNUSUAL_F]
    if not told:
        return ()
    first = next(pair.spec.f for pair in friction if pair.spec.f > UNUSUAL_F)
    # Asked only where the percentage is an f a pair has: 1e6 "% is f = 10000" sent the student further astray.
    percentage = (f": is it a percentage? ({first:g} % is f = {first / 100.0:g})" if first / 100.0 <= UNUSUAL_F
                  else "")
    return (PositionWarning(0, "high-friction", "; ".join(told) + ": few pairs of materials rub with an f above 1 "
                            "(dry steel on steel 0.15 to 0.8, lubricated pairs about 0.1)" + percentage),)


def described(pair: FrictionPair) -> str:
    """A pair with friction as a warning names it: ``the slide at B (links 4–1, f = 0.15)``, ``the journal at A
    (links 2–3, ρ = 0.0015 m)``, a V-guide's by its f′."""
    if pair.sliding:
        coefficient = f"f′ = {pair.coefficient:.4g}" if pair.in_vee else f"f = {pair.coefficient:.4g}"
        return f"the slide at {pair.joint} (links {pair.source}–{pair.target}, {coefficient})"
    return f"the journal at {pair.joint} (links {pair.source}–{pair.target}, ρ = {pair.radius:.4g} m)"


def friction_loads(friction: tuple[FrictionPair, ...], state, reactions: Mapping[str, Vector],
                   senses: tuple | None = None) -> tuple[Load, ...]:
    """The friction loads of the pairs, given their reactions: a moment per turning pair on each of its
    links, a force along the slide per sliding pair (``Mf23`` acts on 3 from 2, ``Mf32`` on 2).

    Loads on the frame are among them; the equations of moving links skip them.  ``senses``: the pairs'
    :func:`rubbing_senses` at ``state``, for a solve that repeats this with other reactions only.
    """
    loads: list[Load] = []
    senses = rubbing_senses(friction, state) if senses is None else senses
    for pair, sense in zip(friction, senses, strict=True):
        magnitude = np.abs(reactions[pair.reaction])
        if not pair.sliding:
            moment = sense * pair.radius * magnitude
            on_target, on_source = pair.load_names
            loads.append(Load(on_target, pair.target, None, 0j, moment))
            loads.append(Load(on_source, pair.source, None, 0j, -moment))
        else:
            force = -pair.coefficient * magnitude * sense
            on_target, on_source = pair.load_names
            loads.append(Load(on_target, pair.target, pair.joint, force, 0.0))
            loads.append(Load(on_source, pair.source, pair.joint, -force, 0.0))
    return tuple(loads)


def rubbing_senses(friction: tuple[FrictionPair, ...], state) -> tuple:
    """What of each pair's friction load its reaction does not change: a turning pair's −sense of turning
    (:func:`turning_sense`), a sliding pair's unit direction of sliding (0 where it neither slides nor is about
    to).  The friction solves repeat :func:`friction_loads` thousands of times at one state."""
    senses: list = []
    moving_scale = state.moving_scale
    for pair in friction:
        if not pair.sliding:
            senses.append(-turning_sense(pair, state))
            continue
        relative = state.sliding[pair.target]
        # At rest in its pair (an extreme position), against the sliding about to begin.
        relative = np.where(at_rest(relative, moving_scale), state.sliding_acceleration.get(pair.target, 0j),
                            relative)
        speed = np.abs(relative)
        with np.errstate(invalid="ignore", divide="ignore"):
            senses.append(np.where(speed > 0, relative / np.where(speed > 0, speed, 1.0), 0j))
    return tuple(senses)


def turning_sense(pair: FrictionPair, state) -> Scalar:
    """The sense a turning pair's target turns in against its source (:func:`loads.sense_of_motion`), which its
    friction moment opposes."""
    target, source = state.links[pair.target], state.links[pair.source]
    return sense_of_motion(target.omega - source.omega, target.epsilon - source.epsilon, state.turning_scale)


__all__ = [
    "UNUSUAL_F",
    "FrictionPair",
    "described",
    "friction_loads",
    "friction_pairs",
    "pair_name",
    "rubbing_senses",
    "turning_sense",
    "unusual_coefficients",
]
