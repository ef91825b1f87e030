"""Kinetostatics of the whole mechanism at once: every reaction and the balancing load as one linear system.

This is the independent check of the force polygons: instead of cutting the
mechanism into groups and closing polygons on a drawing, it writes the three
equilibrium equations (ΣFx, ΣFy, ΣM) of every moving link, with d'Alembert's
inertia loads among the loads, and solves them together at every position
(numpy, batched over positions).  For W = 1 there are exactly as many
unknowns as equations: two per lower pair and the balancing load.

Unknowns: a turning pair's reaction ``R_ij = (Rx, Ry)``, the force the
earlier link i exerts on the later link j at the joint; a sliding pair's
normal force ``N`` (along i·u, u the slide's direction) acting on the
slider at its joint, with a couple ``C = N·x`` that places it ``x`` along the
slide; the driver's balancing moment (a crank) or force along its guide (a
slider).  Friction in the pairs (:mod:`graphplan.joint_friction`) enters as
loads that depend on the reactions, by iteration.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .errors import UnknownNameError
from .joint_friction import FrictionPair, friction_loads, rubbing_senses
from .kinematics import Scalar, Vector, cross, read_only
from .loads import Load, State, motion_state, power
from .mechanism import Mechanism
from .motion import Motion
from .rounding import RELATIVE_NOISE, largest_finite
from .settling import settle

# A system whose condition number exceeds this is singular at that position:
# the reactions are not determined (a toggle of some group), and no number is given.
SINGULAR_CONDITION = 1e12


@dataclass(frozen=True)
class Reaction:
    """The force link ``source`` exerts on link ``target`` through the pair at ``joint``.

    ``force`` is complex (N) over positions.  For a sliding pair it is
    normal to the slide and acts ``offset`` metres along the slide's
    direction from the joint; ``offset`` is None for a turning pair.
    """

    name: str
    joint: str
    source: int
    target: int
    force: Vector
    offset: Scalar | None = None

    @property
    def sliding(self) -> bool:
        return self.offset is not None


@dataclass(frozen=True)
class Equilibrium:
    """Every reaction and the balancing load at every position.

    ``balancing`` is the moment on a driving crank (N·m, ccw positive) or the
    force on a driving slider along its guide (N), that keeps the motion as
    prescribed.  ``singular`` marks positions where the reactions are not
    determined; their values are NaN.  With friction, ``iterations`` counts
    the solutions each position took to settle and ``locked`` marks those
    that never did: the mechanism locks itself there.
    """

    reactions: tuple[Reaction, ...]
    balancing: np.ndarray
    condition: np.ndarray
    singular: np.ndarray
    iterations: np.ndarray
    locked: np.ndarray

    def __post_init__(self) -> None:
        # Handed out as they are (analysis.equilibrium.balancing): a write through them changed what the analysis's
        # sheets, tables and note read after, as a motion's arrays, read-only, cannot.
        arrays = [self.balancing, self.condition, self.singular, self.iterations, self.locked]
        arrays += [value for reaction in self.reactions for value in (reaction.force, reaction.offset)]
        for array in arrays:
            read_only(array)

    def __repr__(self) -> str:
        # The dataclass's own repr printed every reaction's arrays.
        return (f"<Equilibrium at {np.size(self.balancing)} positions: reactions "
                f"{', '.join(reaction.name for reaction in self.reactions)}>")

    def reaction(self, name: str) -> Reaction:
        for reaction in self.reactions:
            if reaction.name == name:
                return reaction
        raise UnknownNameError(f"no reaction {name!r}; reactions are {', '.join(r.name for r in self.reactions)}")


@dataclass(frozen=True)
class Pair:
    """A lower pair as the force analysis names it: ``name`` is the reaction ``R{source}{target}``."""

    name: str
    sliding: bool
    joint: str
    source: int
    target: int


def pairs(mechanism: Mechanism, slides) -> tuple[Pair, ...]:
    """Every lower pair: the turning ones in solution order, then the sliding ones (``Motion.slides``).

    Two pairs between the same links are told apart by their joints (``R23@B``).
    """
    found: list[Pair] = []
    taken: set[str] = set()

    def add(sliding: bool, joint: str, source: int, target: int) -> None:
        name = f"R{source}{target}"
        name = f"{name}@{joint}" if name in taken else name
        taken.add(name)
        found.append(Pair(name, sliding, joint, source, target))

    for joint, source, target in mechanism.revolutes:
        add(False, joint, source, target)
    for slide in slides:
        add(True, slide.joint, slide.guide, slide.slider)
    return tuple(found)


def equilibrium(mechanism: Mechanism, motion: Motion, loads: tuple[Load, ...],
                friction: tuple[FrictionPair, ...] = ()) -> Equilibrium:
    """Solve all the equilibrium equations of all moving links at every position of ``motion``.

    With ``friction`` the friction loads depend on the reactions they change:
    the system is solved again with the friction of the last solution until
    no reaction moves by more than :data:`~graphplan.settling.CONVERGED` of
    the largest, or by Newton's method as the friction is brought in by shares
    (:func:`~graphplan.settling.settle`); a position where that path ends
    locks itself (no finite balancing load moves it).
    """
    count = motion.count
    system = _System(mechanism, motion)
    unknowns, condition, singular, inverse = system.solve(system.known(loads))
    iterations = np.zeros(count, dtype=int)
    locked = np.zeros(count, dtype=bool)
    if friction:
        state = motion_state(motion)

        # The loads without friction are summed once: each repetition adds only the friction's on to them, in
        # the order known(loads + extra) would, so the sums are the same to the last bit.
        summed, senses = system.summed(loads), rubbing_senses(friction, state)

        def repeat(last: np.ndarray) -> np.ndarray:
            extra = friction_loads(friction, state, system.forces(last), senses)
            return system.apply(inverse, -system.summed(extra, summed), singular)

        unknowns, iterations, locked = settle(repeat, unknowns, singular)
    with np.errstate(over="ignore", invalid="ignore"):   # the locked positions' reactions are inf or NaN
        return system.record(unknowns, condition, singular, iterations, locked)


class _System:
    """The equations of one mechanism over all positions: the matrix of the unknowns, the loads' side."""

    def __init__(self, mechanism: Mechanism, motion: Motion) -> None:
        self.mechanism, self.motion = mechanism, motion
        count = self.count = motion.count
        links = mechanism.moving_links
        self.row_of = {number: 3 * index for index, number in enumerate(links)}
        size = 3 * len(links)
        self.matrix = np.zeros((count, size, size))
        self.origins = {number: _full(motion.points[motion.links[number].origin].r, count) for number in links}
        self.pairs = pairs(mechanism, motion.slides)
        for index, pair in enumerate(self.pairs):
            column = 2 * index
            r = motion.points[pair.joint].r
            if pair.sliding:
                normal = 1j * motion.slide(pair.target).u
                for sign, link in ((1.0, pair.target), (-1.0, pair.source)):
                    self._put(link, column, sign * normal, r)
                    self._put(link, column + 1, 0j, r, couple=sign)
            else:
                for sign, link in ((1.0, pair.target), (-1.0, pair.source)):
                    self._put(link, column, sign * (1 + 0j), r)
                    self._put(link, column + 1, sign * 1j, r)
        self.balancing_column = 2 * len(self.pairs)
        driver = mechanism.driver
        if driver.kind == "crank":
            self._put(driver.link, self.balancing_column, 0j, 0j, couple=1.0)
        else:
            self._put(driver.link, self.balancing_column, motion.slide(driver.link).u, motion.points[driver.joint].r)

    def _put(self, link: int, column: int, force: Vector, at: Vector, couple: Scalar = 0.0) -> None:
        """A unit of the unknown in ``column`` acting on ``link``: ``force`` at ``at``, plus ``couple``."""
        if link not in self.row_of:
            return  # the frame: its equations are not written
        row, count = self.row_of[link], self.count
        force = _full(force, count)
        self.matrix[:, row, column] += force.real
        self.matrix[:, row + 1, column] += force.imag
        self.matrix[:, row + 2, column] += cross(_full(at, count) - self.origins[link], force) + couple

    def known(self, loads: tuple[Load, ...]) -> np.ndarray:
        """ΣFx, ΣFy, ΣM of the known loads of every link, moved to the right-hand side."""
        return -self.summed(loads)

    def summed(self, loads: tuple[Load, ...], start: np.ndarray | None = None) -> np.ndarray:
        """ΣFx, ΣFy, ΣM of ``loads`` on every link, added on to ``start`` (the sums of loads before them)."""
        known = np.zeros((self.count, self.matrix.shape[1])) if start is None else start.copy()
        for load in loads:
            if load.link not in self.row_of:
                continue  # on the frame
            row = self.row_of[load.link]
            if load.is_force:
                force = _full(load.force, self.count)
                known[:, row] += force.real
                known[:, row + 1] += force.imag
                line = _full(self.motion.points[load.point].r + load.offset, self.count)
                known[:, row + 2] += cross(line - self.origins[load.link], force)
            else:
                # Added as broadcast_to would give it, without building the view each of the friction's solves.
                known[:, row + 2] += np.asarray(load.moment, dtype=float)
        return known

    def solve(self, rhs: np.ndarray):
        """Solve every position's system once; a singular or undefined one gives NaN and is marked."""
        matrix = self.matrix
        finite = np.all(np.isfinite(matrix), axis=(1, 2)) & np.all(np.isfinite(rhs), axis=1)
        condition = np.full(len(matrix), np.inf)
        if finite.any():
            condition[finite] = np.linalg.cond(matrix[finite])
        singular = ~(condition < SINGULAR_CONDITION)
        inverse = np.full(matrix.shape, np.nan)
        if (~singular).any():
            inverse[~singular] = np.linalg.inv(matrix[~singular])
        return self.apply(inverse, rhs, singular), condition, singular, inverse

    @staticmethod
    def apply(inverse: np.ndarray, rhs: np.ndarray, singular: np.ndarray) -> np.ndarray:
        unknowns = np.einsum("nij,nj->ni", inverse, rhs)
        unknowns[singular] = np.nan
        return unknowns

    def forces(self, unknowns: np.ndarray) -> dict[str, np.ndarray]:
        """Each pair's reaction force (complex) from the unknowns."""
        found = {}
        for index, pair in enumerate(self.pairs):
            first, second = unknowns[:, 2 * index], unknowns[:, 2 * index + 1]
            found[pair.name] = first * 1j * _full(self.motion.slide(pair.target).u, self.count) if pair.sliding \
                else first + 1j * second
        return found

    def record(self, unknowns, condition, singular, iterations, locked) -> Equilibrium:
        forces = self.forces(unknowns)
        reactions = []
        for index, pair in enumerate(self.pairs):
            offset = None
            if pair.sliding:
                normal, couple = unknowns[:, 2 * index], unknowns[:, 2 * index + 1]
                with np.errstate(invalid="ignore", divide="ignore"):
                    offset = np.where(normal != 0, couple / normal, 0.0)
            reactions.append(Reaction(pair.name, pair.joint, pair.source, pair.target, forces[pair.name], offset))
        return Equilibrium(tuple(reactions), unknowns[:, self.balancing_column], condition, singular, iterations, locked)


def balancing_by_power(mechanism: Mechanism, state: State, loads: tuple[Load, ...]) -> Scalar:
    """The balancing load from the power balance ``Mb·ω1 + Σ(F·v + M·ω) = 0`` (ideal pairs do no work).

    For a driving slider the balancing force: ``Fb·v1 + Σ(F·v + M·ω) = 0``.
    """
    driver = mechanism.driver
    if driver.kind == "crank":
        speed = state.links[driver.link].omega
    else:
        speed = driver.velocity
    return -power(loads, state) / speed


# A balancing load without friction this small beside the one with it is rounding of a zero (an extreme
# position, where the loads take no power): η is then 0, all the driver's power going into friction.
_ROUNDING_OF_ZERO = 1e-9


def balancing_scale(ideal: Scalar) -> float:
    """The largest balancing load without friction over the positions (finite ones): the scale ``scale`` of
    :func:`efficiency`, :func:`turned_round` and :func:`rounded_zero` judges rounding against."""
    return largest_finite(np.asarray(ideal, dtype=float))


def efficiency(mechanism: Mechanism, ideal: Scalar, rubbing: Scalar, scale: float = 0.0) -> Scalar:
    """The instantaneous efficiency from the balancing load without and with friction.

    η = Mb0/Mb where the driver delivers power (Mb0·ω1 > 0); where the load
    drives the driver the power flows back, and η = Mb/Mb0.  Below 1 with
    friction, 1 without, 0 where the loads take no power (Mb0 rounding of a zero beside Mb, or beside
    ``scale``, the cycle's largest Mb0: :func:`balancing_scale`).  Where friction
    turns the flow round (:func:`turned_round`) no power is passed on in
    either sense, and η is not defined (NaN).
    """
    ideal, rubbing = np.asarray(ideal, dtype=float), np.asarray(rubbing, dtype=float)
    idle = _idle(ideal, rubbing, scale)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        ratio = np.where(delivers_power(mechanism, ideal), ideal / rubbing, rubbing / ideal)
        return np.where(idle, 0.0, np.where(ideal * rubbing > 0, ratio, np.nan))


def turned_round(mechanism: Mechanism, ideal: Scalar, rubbing: Scalar, scale: float = 0.0) -> np.ndarray:
    """Where the loads would drive the driver back (η = Mb/Mb0) but with friction the driver must drive: the
    mechanism locks itself against its loads driving it (η′ ≤ 0), and the driver pushes it through.  An Mb0
    that is rounding of a zero (``scale`` as :func:`efficiency` takes it) drives nothing."""
    ideal, rubbing = np.asarray(ideal, dtype=float), np.asarray(rubbing, dtype=float)
    speed = mechanism.driver.coordinate_speed
    with np.errstate(invalid="ignore"):
        return (~delivers_power(mechanism, ideal) & ~_idle(ideal, rubbing, scale) & (rubbing * speed >= 0)
                & np.isfinite(ideal) & np.isfinite(rubbing))


def rounded_zero(ideal: Scalar, rubbing: Scalar, scale: float = 0.0) -> Scalar:
    """The balancing load without friction, 0 where it is rounding of a zero beside the one with friction or
    beside ``scale`` (as :func:`efficiency` takes it)."""
    ideal = np.asarray(ideal, dtype=float)
    return np.where(_idle(ideal, np.asarray(rubbing, dtype=float), scale), 0.0, ideal)


def _idle(ideal: np.ndarray, rubbing: np.ndarray, scale: float) -> np.ndarray:
    size = np.abs(ideal)
    # Where the pairs rub no harder there (a slide's normal reaction is 0 at a slider-crank's dead centre, or
    # f = 0), Mb is the same rounding as Mb0, and beside it Mb0 is no smaller: it is told from the cycle's
    # largest Mb0 instead, by the rule results.json writes a value as 0 by (rounding.noise_floor).
    return (size <= _ROUNDING_OF_ZERO * np.abs(rubbing)) | (size <= RELATIVE_NOISE * scale)


def delivers_power(mechanism: Mechanism, ideal: Scalar) -> np.ndarray:
    """Whether η is Mb0/Mb: the driver delivers power against the balancing load ``ideal`` without friction,
    or the loads take none (η = 0 is then Mb0/Mb: the driver's power all goes into friction, and Mb/Mb0 would
    divide by 0); not where the loads drive the driver back (η = Mb/Mb0)."""
    driver = mechanism.driver
    speed = driver.coordinate_speed
    return np.asarray(ideal, dtype=float) * speed >= 0


def _full(value: Vector | Scalar, count: int) -> np.ndarray:
    return np.broadcast_to(np.asarray(value, dtype=complex), (count,))


__all__ = ["SINGULAR_CONDITION", "Equilibrium", "Pair", "Reaction", "balancing_by_power", "balancing_scale",
           "delivers_power", "efficiency", "equilibrium", "pairs", "rounded_zero", "turned_round"]
