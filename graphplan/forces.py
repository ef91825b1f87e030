"""The force analysis of one position, group by group, as it is drawn.

The groups are cut free from the last one of the structure formula back to
the driver.  Each group kind solves its own equilibrium on a
:class:`ForceBoard` (``construct_forces`` in its module): moment equations
about a joint, with the arm of every load measured on the drawing, give the
components across the links; the force polygon of the group, closed by
crossing two lines of action, gives the rest.  A reaction a group finds on a
link of an earlier group is applied to that link, reversed, when its turn
comes; the driver ends with the balancing moment (or force).

Everything is computed from the plans of the position (inertia loads from
the acceleration plan), never from the analytic solution: the whole-mechanism
linear system of :mod:`graphplan.statics` is the independent check.

The record (:class:`ForcePlan`) keeps each moment equation with its terms
and arms and each polygon with its vectors and closing lines, so that the
sheets and the note read what was done.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING

import numpy as np

from .geometry import Line, ParallelLinesError, cross_lines, crossing_angle_deg
from .kinematics import Scalar, Vector, cross
from .lookalikes import NamedValues
from .plans import guide_at
from .scales import standard_scale
from .settling import settle

if TYPE_CHECKING:
    from .mechanism import Mechanism

# The field a force polygon gets on the sheet when μF is chosen, mm.
POLYGON_FIELD_MM = 150.0
# A polygon drawn at another analysis's μF (with friction, at the one without) keeps it up to this many fields.
_KEPT_FIELDS = 2.0
# A polygon whose vertices all lie this close to one line (a share of its extent) has no area: vectors on one line
# (R32 and R12 of a crank with no weight) are that far off it by the arithmetic's rounding alone, some 1e-16.
_FLAT = 1e-9
# A force whose line passes this close to a moment centre (a share of the mechanism's size) passes through it.
_THROUGH = 1e-12
# A term's moment this small beside its equation's largest is the plan's rounding (an inertia moment of a link at
# rest in its turning), not a moment: the note leaves it out by the same share (report.forces.ROUNDING).
TERM_ROUNDING = 1e-12
# A force less than this share of the largest on its group cut free is a rounding error: the force sheet draws no
# arrow for it, so no arm of it is named (:attr:`GroupForces.arm_names`), and the lever none at its point.
NEGLIGIBLE = 1e-9


def negligible(force: complex, forces: Sequence[complex]) -> bool:
    """Whether a force is nought beside the others (a rounding error): it is not drawn.

    A small force that is there (a link's weight beside the inertia loads)
    is drawn, at least the force sheet's least arrow long.
    """
    return abs(force) <= NEGLIGIBLE * max((abs(other) for other in forces), default=0.0)


@dataclass(frozen=True)
class Load:
    """A force ``force`` at ``point`` of ``link``, or a moment ``moment`` on it (``point`` None).

    ``name`` is the textbook's: ``G3`` weight, ``Fu3`` inertia force,
    ``Mu3`` inertia moment, ``F4``/``M4`` an external load (numbered when a
    link has several: ``F4.2``).  A force's line of action passes
    ``offset`` (m) from its point: the resultant of a link's inertia loads,
    displaced by h = Mu/Fu so that its moment about the centre is Mu.
    """

    name: str
    link: int
    point: str | None
    force: Vector
    moment: Scalar
    offset: Vector = 0j

    @property
    def is_force(self) -> bool:
        return self.point is not None


@dataclass(frozen=True)
class Term:
    """One term of a moment equation: ``name``'s moment about the centre, with its arm ``arm`` (m)."""

    name: str
    moment: float
    arm: float


@dataclass(frozen=True)
class MomentEquation:
    """ΣM_about(link) = 0 solved for ``unknown``: ``value`` along the direction first assumed.

    A negative ``value`` means the first guess of the sense was wrong: the
    component is turned round, as the textbook does.  ``couple``: the unknown
    is a moment (Mb, a normal force's shift times the force, R14·x), in N·m,
    not a force.
    """

    link: int
    about: str
    terms: tuple[Term, ...]
    unknown: str
    value: float
    arm: float
    links: tuple[int, ...] = ()
    couple: bool = False

    @property
    def bodies(self) -> str:
        """What the equation is written for: ``3``, or ``3,4,5,6`` for a whole group (``links``)."""
        return ",".join(map(str, self.links)) if self.links else str(self.link)

    @property
    def standing_terms(self) -> tuple[Term, ...]:
        """The terms every writing of the equation keeps: all but the rounding, however short their arms.

        Their moments are what the value balances, so an equation written with
        these alone still gives its value.
        """
        size = max([abs(term.moment) for term in self.terms] + [abs(self.value * self.arm)])
        return tuple(term for term in self.terms if abs(term.moment) > TERM_ROUNDING * size)

    @property
    def equation(self) -> str:
        """``ΣMB(3) = R23τ·h + M(G3) − M(Fu3) + … = 0``, the moments' signs as found (ccw positive)."""
        parts = "".join(f" {'+' if term.moment >= 0 else '−'} M({term.name})" for term in self.terms)
        return f"ΣM{self.about}({self.bodies}) = {self.unknown}·h{parts} = 0"


@dataclass(frozen=True)
class ProjectionEquation:
    """ΣF(link) projected on a slide = 0, solved for ``unknown`` along it: a block in a slot takes no force along the
    slot, so its pin's reaction balances the block's own loads along it.  ``components`` are each load's part along
    the slide (N), signed along its direction."""

    link: int
    components: tuple[tuple[str, float], ...]
    unknown: str
    value: float


@dataclass(frozen=True)
class PolygonVector:
    """A vector of a force polygon from ``start`` to ``end`` (N, on the polygon's own plane)."""

    name: str
    start: complex
    end: complex
    role: str  # "load" (known, laid off), "closing" (found by crossing), "inner" (read off afterwards)

    @property
    def force(self) -> complex:
        return self.end - self.start


@dataclass(frozen=True)
class Polygon:
    """ΣF = 0 of a group (or of the driver) closed on the drawing."""

    equation: str
    vectors: tuple[PolygonVector, ...]
    lines: tuple[Line, ...] = ()
    crossing_deg: float | None = None

    @property
    def equations(self) -> tuple[str, ...]:
        """The polygon's equations one by one: a group of a link and a block closes two, written ``…= 0;  …= 0``."""
        return tuple(part.strip() for part in self.equation.split(";") if part.strip())


@dataclass(frozen=True)
class Found:
    """A reaction the construction found: ``force`` of ``source`` on ``target`` at ``joint`` (+ ``offset`` m along a slide)."""

    name: str
    joint: str
    source: int
    target: int
    force: complex
    offset: float | None = None

    @property
    def back(self) -> Found:
        """The same reaction as the target acts back on the source: ``R32`` of ``R23``."""
        return replace(self, name=f"R{self.target}{self.source}", source=self.target, target=self.source,
                       force=-self.force)


@dataclass(frozen=True)
class BodyForce:
    """A force on a group cut free: a ``load`` of its links (a reaction a later group handed back among them), a
    ``reaction`` found on it from outside, whole or the part of it its polygon lays (R23τ), or, with neither, the
    slider driver's balancing force Fb."""

    name: str
    force: complex
    load: Load | None = None
    reaction: Found | None = None


@dataclass(frozen=True)
class GroupForces:
    """One group cut free: its loads, its moment equations, its polygon, the reactions found, and μF (N/mm)
    its polygon is drawn at."""

    label: str
    links: tuple[int, ...]
    loads: tuple[Load, ...]
    moments: tuple[MomentEquation, ...]
    polygon: Polygon
    found: tuple[Found, ...]
    scale: float = 1.0
    projections: tuple[ProjectionEquation, ...] = ()

    @property
    def body_forces(self) -> tuple[BodyForce, ...]:
        """Every force on the group cut free: its loads, the reactions found on it, a slider driver's Fb.

        A reaction is split as the group's polygon splits it (R23τ, R23n);
        reactions between the group's own links are inner and are no force on it.
        """
        forces = [BodyForce(load.name, load.force, load=load) for load in self.loads if load.is_force and load.force != 0]
        polygon = {vector.name: vector for vector in self.polygon.vectors if vector.role != "inner"}
        for found in self.found:
            if found.source in self.links:
                continue
            parts = [polygon[name] for name in (f"{found.name}τ", f"{found.name}n") if name in polygon]
            if parts:
                forces.extend(BodyForce(part.name, part.force, reaction=found) for part in parts)
            else:
                forces.append(BodyForce(found.name, found.force, reaction=found))
        if "Fb" in polygon:
            forces.append(BodyForce("Fb", polygon["Fb"].force))
        return tuple(forces)

    @property
    def shown_forces(self) -> tuple[BodyForce, ...]:
        """The forces on the group cut free that are there: all but a rounding error's (:func:`negligible`)."""
        forces = self.body_forces
        return tuple(force for force in forces if not negligible(force.force, [other.force for other in forces]))

    @property
    def arm_names(self) -> tuple[tuple[str | None, ...], ...]:
        """For each moment equation, the name of the arm of each of its standing terms (h1, h2, …, numbered on
        through the group's equations), None for a term with no arm of its own to name.

        A term has its arm named where its force is one the group cut free
        shows (:attr:`shown_forces`), however short the arm: a couple (Mu3),
        a term the group adds that is no force on it (R·x) and a rounding
        error's force have none.  The force sheet letters its arms by these
        names and the note writes each term's F·h with them, so that the note's
        h2 is the sheet's.
        """
        shown = {force.name for force in self.shown_forces}
        count = 0
        names = []
        for equation in self.moments:
            row: list[str | None] = []
            for term in equation.standing_terms:
                if term.name in shown:
                    count += 1
                    row.append(f"h{count}")
                else:
                    row.append(None)
            names.append(tuple(row))
        return tuple(names)

    def held_as_couple_alone(self, equation: MomentEquation) -> str | None:
        """The reaction whose moment R·x its guide holds as a couple alone, or None.

        Where a guide's normal reaction is nought (the Scotch yoke's) and its moment is not, R·x beside R = 0
        would put the line of R at infinity: the guide carries the moment as a couple.  The sheet and the note
        both ask here, so that neither writes an x the other calls absent.
        """
        if not equation.unknown.endswith("·x"):
            return None
        reaction = equation.unknown[:-2]
        found = {item.name: item.force for item in self.found}
        strongest = max((abs(force) for force in found.values()), default=0.0)
        if reaction in found and abs(found[reaction]) <= TERM_ROUNDING * strongest and \
                abs(equation.value) > TERM_ROUNDING * max(strongest, 1.0):
            return reaction
        return None


@dataclass(frozen=True)
class ForcePlan:
    """The force analysis of one position: groups in the order solved (last group first, driver last).

    ``scale`` is μF (N/mm) at which every polygon of the position fits its
    field, the contract's ``polygon_scale``; each group's polygon is drawn
    at its own ``GroupForces.scale``, the same unless the scene leaves μF to
    the program, which then draws each polygon as large as its field allows,
    as a student sets each group's force plan at its own scale (but one of
    no area, its vectors on one line, at the others' coarsest μF).
    ``iterations`` is how many times the construction was repeated for the
    friction in the pairs (0 without); ``locked`` says that it never settled.
    ``auxiliary`` holds the moment centres that are no point of the scene
    (Assur's special point ``Σ6`` of a triad), where they lie (m).
    """

    groups: tuple[GroupForces, ...]
    reactions: Mapping[str, Found]
    balancing: float
    scale: float
    iterations: int = 0
    locked: bool = False
    auxiliary: Mapping[str, complex] = field(default_factory=dict)

    def __post_init__(self) -> None:
        object.__setattr__(self, "reactions", NamedValues(self.reactions, "is no reaction the force analysis finds, "
                                                                          "which finds"))

    def __repr__(self) -> str:
        # The dataclass's own repr printed every polygon's vectors (some 8 000 characters).
        return (f"<ForcePlan of {len(self.groups)} groups: reactions {', '.join(self.reactions)}; "
                f"balancing {self.balancing:.5g}; μF = {self.scale:g} N/mm>")

    @property
    def group_scales(self) -> dict[str, float]:
        """μF of each group's polygon, by the group's label."""
        return {group.label: group.scale for group in self.groups}

    @property
    def one_scale(self) -> bool:
        """Whether every polygon is drawn at the position's μF."""
        return all(group.scale == self.scale for group in self.groups)

    def scale_of(self, reaction: str) -> float:
        """μF of the polygon that finds ``reaction`` (the position's μF for one no polygon finds)."""
        return next((group.scale for group in self.groups if any(found.name == reaction for found in group.found)),
                    self.scale)

    def at_scale(self, scale: float) -> ForcePlan:
        """The same analysis with every polygon at μF = ``scale``."""
        return replace(self, groups=tuple(replace(group, scale=scale) for group in self.groups), scale=scale)


@dataclass
class ForceBoard:
    """The drawing board of the force analysis of one position (mutable only while it is built)."""

    mechanism: Mechanism
    positions: dict[str, complex]
    directions: Mapping[int, complex]
    loads: tuple[Load, ...]
    applied: dict[int, list[Load]] = field(default_factory=dict)
    reactions: dict[str, Found] = field(default_factory=dict)
    groups: list[GroupForces] = field(default_factory=list)
    balancing: float = 0.0
    auxiliary: dict[str, complex] = field(default_factory=dict)
    _moments: list[MomentEquation] = field(default_factory=list)
    _projections: list[ProjectionEquation] = field(default_factory=list)
    _found: list[Found] = field(default_factory=list)

    # What a group asks while it solves.
    def loads_on(self, link: int) -> list[Load]:
        """The link's own loads, then the reactions later groups put on it."""
        return [load for load in self.loads if load.link == link] + self.applied.get(link, [])

    def force_sum(self, *links: int) -> complex:
        return sum((load.force for link in links for load in self.loads_on(link) if load.is_force), 0j)

    def guide_line(self, guide) -> tuple[complex, complex, int]:
        return guide_at(self.mechanism, self.positions, self.directions, guide)

    def moment_terms(self, link: int, about: complex) -> tuple[Term, ...]:
        """The moments of the link's loads about ``about``, each with its arm (m)."""
        terms = []
        size = max(abs(position) for position in self.positions.values())
        for load in self.loads_on(link):
            if load.is_force:
                moment = cross(self.positions[load.point] + load.offset - about, load.force)
                arm = abs(moment) / abs(load.force) if abs(load.force) > 0 else 0.0
                if arm > _THROUGH * size:  # a force through the centre has no arm, whatever rounding says
                    terms.append(Term(load.name, float(moment), float(arm)))
            elif load.moment != 0:
                terms.append(Term(load.name, float(load.moment), 0.0))
        return tuple(terms)

    def solve_moment(self, link: int, about: str, unknown: str, direction: complex, at: complex,
                     extra: tuple[Term, ...] = ()) -> float:
        """ΣM_about = 0 for the magnitude of a force along unit ``direction`` through ``at``."""
        return self.solve_moment_of((link,), about, unknown, direction, at, extra)

    def solve_moment_of(self, links: tuple[int, ...], about: str, unknown: str, direction: complex, at: complex,
                        extra: tuple[Term, ...] = ()) -> float:
        """:meth:`solve_moment` for several links cut free together (a whole group about Assur's point)."""
        centre = self.positions[about]
        terms = tuple(term for link in links for term in self.moment_terms(link, centre)) + extra
        lever = float(cross(at - centre, direction))
        value = -sum(term.moment for term in terms) / lever
        self._moments.append(MomentEquation(links[0], about, terms, unknown, value, abs(lever),
                                            links=links if len(links) > 1 else ()))
        return value

    def add_centre(self, name: str, where: complex) -> None:
        """A moment centre that is no point of the scene (Assur's special point)."""
        self.positions[name] = where
        self.auxiliary[name] = where

    def solve_projection(self, link: int, unknown: str, direction: complex) -> float:
        """ΣF(link)·u = 0 for the magnitude of a force along unit ``direction`` (u)."""
        components = tuple((load.name, float((load.force * direction.conjugate()).real))
                           for load in self.loads_on(link) if load.is_force and load.force != 0)
        value = -sum(component for _, component in components)
        self._projections.append(ProjectionEquation(link, components, unknown, value))
        return value

    def couple(self, link: int, about: str, unknown: str, extra: tuple[Term, ...] = ()) -> float:
        """ΣM_about = 0 for a couple (a normal force's shift along its slide times the force)."""
        terms = self.moment_terms(link, self.positions[about]) + extra
        value = -sum(term.moment for term in terms)
        self._moments.append(MomentEquation(link, about, terms, unknown, value, 1.0, couple=True))
        return value

    def react(self, name: str, joint: str, source: int, target: int, force: complex,
              offset: float | None = None) -> Found:
        """Record a reaction; an earlier link it comes from gets the reaction back, reversed."""
        found = Found(name, joint, source, target, complex(force), offset)
        self.reactions[name] = found
        self._found.append(found)
        return found

    def source_of(self, joint: str, link: int) -> int:
        """The earlier link that ``link`` is pinned to at ``joint``."""
        return next(source for name, source, target in self.mechanism.revolutes if name == joint and target == link)

    def hand_back(self, found: Found, at: complex | None = None) -> None:
        """Apply ``found`` reversed to its source link, which an earlier group solves later.

        ``at`` is where it acts when that is not the joint itself (a normal
        force shifted along its slide).
        """
        if found.source == self.mechanism.scene.frame_link:
            return
        point = found.joint
        if at is not None and at != self.positions[found.joint]:
            point = f"{found.joint}({found.name})"
            self.positions[point] = at
        back = found.back
        self.applied.setdefault(found.source, []).append(Load(back.name, found.source, point, back.force, 0.0))

    def finish_group(self, label: str, links: tuple[int, ...], polygon: Polygon) -> None:
        loads = tuple(load for link in links for load in self.loads_on(link))
        self.groups.append(GroupForces(label, links, loads, tuple(self._moments), polygon, tuple(self._found),
                                       projections=tuple(self._projections)))
        self._moments, self._projections, self._found = [], [], []


class PolygonBuilder:
    """A force polygon laid off vector after vector, closed by two lines of action."""

    def __init__(self, equation: str) -> None:
        self.equation = equation
        self.vectors: list[PolygonVector] = []
        self.lines: list[Line] = []
        self.crossing_deg: float | None = None
        self.start = 0j
        self.end = 0j

    def lay(self, name: str, force: complex, role: str = "load") -> complex:
        """Lay ``force`` off from the current end; returns the new end."""
        if force != 0:
            self.vectors.append(PolygonVector(name, self.end, self.end + force, role))
            self.end = self.end + force
        return self.end

    def lay_all(self, loads: list[Load]) -> complex:
        for load in loads:
            if load.is_force:
                self.lay(load.name, load.force)
        return self.end

    def close(self, last: str, last_direction: complex, first: str, first_direction: complex) -> tuple[complex, complex]:
        """Close the polygon: ``last`` along its line through the end, ``first`` along its line through the start.

        Returns the two closing forces (``last`` then ``first``).
        """
        lines = (Line(self.end, last_direction, last), Line(self.start, first_direction, first))
        extent = max([abs(v.end) for v in self.vectors] + [abs(self.start), abs(self.end), 1.0])
        vertex = cross_lines(lines[0], lines[1], extent)
        self.crossing_deg = crossing_angle_deg(*lines)
        self.lines.extend(lines)
        last_force, first_force = vertex - self.end, self.start - vertex
        self.vectors.append(PolygonVector(last, self.end, vertex, "closing"))
        self.vectors.append(PolygonVector(first, vertex, self.start, "closing"))
        self.end = self.start
        return last_force, first_force

    def closing(self, name: str) -> complex:
        """The single unknown that closes the polygon from its end back to its start."""
        force = self.start - self.end
        self.vectors.append(PolygonVector(name, self.end, self.start, "closing"))
        self.end = self.start
        return force

    def inner(self, name: str, start: complex, end: complex) -> complex:
        """A reaction read off the polygon between two of its vertices."""
        self.vectors.append(PolygonVector(name, start, end, "inner"))
        return end - start

    def record(self) -> Polygon:
        return Polygon(self.equation, tuple(self.vectors), tuple(self.lines), self.crossing_deg)


def force_plan(mechanism: Mechanism, positions: Mapping[str, complex], directions: Mapping[int, complex],
               loads: tuple[Load, ...], scale: float | Mapping[str, float] | None = None,
               friction: Callable[[Mapping[str, complex]], tuple[Load, ...]] | None = None) -> ForcePlan:
    """The force analysis of the instant: every group from the last to the first, then the driver.

    ``scale`` is μF of every polygon (the scene's), or of each group's by
    its label (another analysis's :attr:`ForcePlan.group_scales`, kept while
    the polygon spans no more than two fields at it); None
    draws each polygon at the least standard μF at which it spans
    :data:`POLYGON_FIELD_MM`, but one of no area at the coarsest μF of the
    others where that is coarser (:func:`_chosen_scales`).
    ``friction`` gives the pairs' friction loads for given reactions
    (``joint_friction.friction_loads`` bound to the instant): the whole
    construction is then repeated with the friction loads of the last one
    until the reactions settle; the record says how many times, and whether
    they never did (the mechanism locks itself).
    """
    plan = _construct(mechanism, positions, directions, loads)
    iterations, locked = 0, False
    if friction is not None:
        plan, iterations, locked = _with_friction(plan, lambda extra: _construct(
            mechanism, positions, directions, loads + extra), friction)
    if scale is None:
        scales = _chosen_scales(plan.groups)
    elif isinstance(scale, Mapping):
        # Another analysis's μF (the one without friction), kept for the two to be compared while the polygon
        # stays about its field: near a lock friction grows the reactions tenfold and more, and the polygon
        # takes a μF of its own rather than metres of paper.
        scales = {group.label: scale[group.label] if polygon_extent(group.polygon) <= _KEPT_FIELDS *
                  POLYGON_FIELD_MM * scale[group.label] else (_fitting_scale(group.polygon) or scale[group.label])
                  for group in plan.groups}
    else:
        scales = dict.fromkeys((group.label for group in plan.groups), scale)
    groups = tuple(replace(group, scale=scales[group.label]) for group in plan.groups)
    # μF of the position: the scene's, else the coarsest polygon's, at which every polygon fits its field.
    position_scale = scale if isinstance(scale, float | int) else max(scales.values(), default=1.0)
    return ForcePlan(groups, plan.reactions, plan.balancing, float(position_scale), iterations, locked, plan.auxiliary)


def _with_friction(ideal: ForcePlan, construct: Callable[[tuple[Load, ...]], ForcePlan],
                   friction: Callable[[Mapping[str, complex]], tuple[Load, ...]]) -> tuple[ForcePlan, int, bool]:
    """The construction repeated with the friction loads of the reactions the last one found, from ``ideal``
    (without friction) until they settle (:func:`~graphplan.settling.settle`): the last construction, how many
    times it was made, and whether the position locks itself."""
    names = tuple(ideal.reactions)
    made: dict[bytes, ForcePlan] = {}

    def repeat(rows: np.ndarray) -> np.ndarray:
        found = np.full(rows.shape, np.nan, dtype=complex)
        for row, forces in zip(found, rows, strict=True):
            if not np.all(np.isfinite(forces)):  # blown up: no construction follows from it
                continue
            try:
                again = construct(friction(dict(zip(names, forces, strict=True))))
            except ParallelLinesError:  # reactions blown up past any number: their lines point nowhere
                continue
            row[:] = [again.reactions[name].force for name in names]
            made.clear()
            made[row.tobytes()] = again
        return found

    start = np.array([[ideal.reactions[name].force for name in names]])
    settled, iterations, locked = settle(repeat, start)
    if locked[0]:  # no construction to show: the position's record is the one without friction, marked locked
        return ideal, int(iterations[0]), True
    plan = made.get(settled[0].tobytes())  # the repetitions' last construction, as it was made
    if plan is None:  # Newton's method settled between constructions
        plan = construct(friction(dict(zip(names, settled[0], strict=True))))
    return plan, int(iterations[0]), False


def _chosen_scales(groups: tuple[GroupForces, ...]) -> dict[str, float]:
    """μF of each group's polygon, by its label, where the scene sets none: the least standard one at which it spans
    :data:`POLYGON_FIELD_MM` (:func:`_fitting_scale`), except for a polygon of no area.

    A polygon of no area, its vectors all on one line (a crank with no weight of its own: R32 and R12 opposite,
    ΣF2 + R12 = 0), shows no more at its field than at the μF of the polygon whose reaction it carries, and at its
    field its thin diagonal takes a sheet's room on its own: it is drawn at the coarsest μF of the polygons that
    have an area, where that is coarser than its own, never larger than its field.  A polygon of no length (a group
    with nothing to balance) takes the coarsest of all the others'.
    """
    fitting = {group.label: _fitting_scale(group.polygon) for group in groups}
    flat = {group.label for group in groups if fitting[group.label] is not None and _has_no_area(group.polygon)}
    with_area = [value for label, value in fitting.items() if value is not None and label not in flat]
    coarsest = max((value for value in fitting.values() if value is not None), default=1.0)
    coarsest_with_area = max(with_area, default=0.0)
    return {label: coarsest if value is None else max(value, coarsest_with_area) if label in flat else value
            for label, value in fitting.items()}


def _has_no_area(polygon: Polygon) -> bool:
    """Whether every vertex of ``polygon`` lies on the line through its two farthest apart, to :data:`_FLAT` of
    their distance."""
    vertices = [vector.start for vector in polygon.vectors] + [vector.end for vector in polygon.vectors]
    first, second = max(((one, other) for one in vertices for other in vertices),
                        key=lambda pair: abs(pair[1] - pair[0]))
    extent = abs(second - first)
    along = (second - first) / extent
    return all(abs(((vertex - first) / along).imag) <= _FLAT * extent for vertex in vertices)


def _fitting_scale(polygon: Polygon) -> float | None:
    """The least standard μF at which ``polygon`` spans at most :data:`POLYGON_FIELD_MM`; None for no span."""
    extent = polygon_extent(polygon)
    return standard_scale(extent / POLYGON_FIELD_MM) if extent > 0 else None


def polygon_extent(polygon: Polygon) -> float:
    """The largest distance between two vertices of ``polygon`` (N): what its μF must fit."""
    return max((abs(vector.end - other.end) for vector in polygon.vectors for other in polygon.vectors),
               default=0.0)


def _construct(mechanism: Mechanism, positions: Mapping[str, complex], directions: Mapping[int, complex],
               loads: tuple[Load, ...]) -> ForcePlan:
    board = ForceBoard(mechanism, dict(positions), directions, loads)
    for group in reversed(mechanism.groups):
        group.construct_forces(board)
    mechanism.driver.construct_forces(board)
    return ForcePlan(tuple(board.groups), dict(board.reactions), board.balancing, 1.0, auxiliary=dict(board.auxiliary))


__all__ = [
    "ForceBoard",
    "ForcePlan",
    "Found",
    "GroupForces",
    "Load",
    "MomentEquation",
    "Polygon",
    "PolygonBuilder",
    "PolygonVector",
    "Term",
    "force_plan",
    "polygon_extent",
]
