"""Velocity and acceleration plans, constructed as a student draws them.

A plan is built group by group in the order of the structure formula, from
the positions of the mechanism at one instant and the driver's motion alone:
known vectors are laid off, lines of action are drawn through their ends and
crossed (:mod:`graphplan.geometry`), further points follow by similarity.
Nothing here reads the analytic velocities or accelerations, so that the
error table compares two independent methods.

Each plan is a record of its construction (:class:`Plan`): the steps with
their vector equations, the vectors laid off, the lines drawn, the points
fixed, and the scale.  The construction itself runs in SI units (m/s, m/s²);
the scale turns it into millimetres once the plan's size is known.
"""

from __future__ import annotations

import math
from collections.abc import Collection, Mapping
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING, Literal, get_args

from .geometry import (
    Line,
    ParallelLinesError,
    cross_lines,
    crossing_angle_deg,
    similar_point,
    turned,
)
from .lookalikes import plan_letter
from .scales import standard_scale

if TYPE_CHECKING:
    from .mechanism import Mechanism

# The field a plan gets on the sheet when the scene fixes no scale, in mm.
PLAN_FIELD_MM = 150.0
# Lines of action crossing at less than this angle make a reading untrustworthy.
SHALLOW_CROSSING_DEG = 5.0


def image_name(point: str) -> str:
    """The plan's letter for a point of the mechanism: ``B`` → ``b``, ``S3`` → ``s3``, P → ``p′`` (``p`` is the
    pole's); the reader refuses two points lettered alike (:func:`graphplan.mechanism.build`)."""
    return plan_letter(point)


@dataclass(frozen=True)
class LaidVector:
    """A vector of the plan from ``start`` to ``end`` (plan letters); ``meaning`` is its name (``vBA``)."""

    start: str
    end: str
    meaning: str


LineKind = Literal["perpendicular", "parallel", "guide", "frame_line", "slot", "slide"]
_LINE_KINDS = frozenset(get_args(LineKind))


@dataclass(frozen=True)
class LineMeaning:
    """What a line of action is drawn along, as fields a report can word in any language.

    ``perpendicular`` and ``parallel`` lines run square to or along the
    segment between the mechanism's ``points`` (``⊥ AB``, ``∥ CA``); a
    ``guide`` line along a guide on the frame (``link`` None) or on ``link``,
    naming in ``points`` the slider's pin whose sliding it carries where Assur's
    point lies on the guide's normal there;
    a ``frame_line`` along the frame line ``name``; a ``slot`` line along the
    slot cut in ``link``; a ``slide`` line along the slide of ``link`` where
    it misses the link's points.
    """

    kind: LineKind
    points: tuple[str, ...] = ()
    link: int | None = None
    name: str = ""

    def __post_init__(self) -> None:
        if self.kind not in _LINE_KINDS:
            raise ValueError(f"a line of action is one of {sorted(_LINE_KINDS)}, not {self.kind!r}")
        if self.kind in ("perpendicular", "parallel") and len(self.points) != 2:
            raise ValueError(f"a {self.kind} line of action names two points, not {self.points!r}")
        if self.kind in ("slot", "slide") and self.link is None:
            raise ValueError(f"a {self.kind} line of action names its link")
        if self.kind == "frame_line" and not self.name:
            raise ValueError("a frame_line line of action names its frame line")

    @property
    def parallel(self) -> bool:
        """Whether the line runs along a slide (``∥ …``) rather than square to a link (``⊥ …``)."""
        return self.kind != "perpendicular"

    @property
    def text(self) -> str:
        """The line as drawings and records name it: ``⊥ AB``, ``∥ guide on link 4``, ``∥ slot``."""
        if self.kind == "perpendicular":
            return "⊥ " + "".join(self.points)
        if self.kind == "parallel":
            return "∥ " + "".join(self.points)
        if self.kind == "guide":
            return "∥ guide" if self.link is None else f"∥ guide on link {self.link}"
        if self.kind == "frame_line":
            return f"∥ {self.name}"
        if self.kind == "slot":
            return "∥ slot"
        return f"∥ slide of link {self.link}"


@dataclass(frozen=True)
class DrawnLine:
    """A line of action through the plan point ``through``, along ``direction``; ``along`` says what it follows."""

    through: str
    direction: complex
    along: LineMeaning

    @property
    def meaning(self) -> str:
        """The line's name as the drawings and records show it (``⊥ AB``, ``∥ guide``)."""
        return self.along.text


@dataclass(frozen=True)
class Similarity:
    """How the plan point ``letter``, the image of ``link``'s point ``point``, was placed by the similarity theorem.

    The figure of the two images ``basis`` already on the plan and ``letter``
    is similar to that of the points ``basis_points`` and ``point`` on the
    link (``abe ∼ ABE``).  A link with fewer than two images on the plan
    (``basis`` empty) takes the figure of the link it turns with,
    ``turns_with``.  ``point`` may name a link's point over a joint (``B4``,
    link 4's point under B).
    """

    letter: str
    point: str
    link: int
    basis: tuple[str, ...] = ()
    basis_points: tuple[str, ...] = ()
    turns_with: int | None = None

    def __post_init__(self) -> None:
        if len(self.basis) not in (0, 2) or len(self.basis_points) != len(self.basis):
            raise ValueError(f"a similarity is built on two images and their two points, not {self.basis!r} "
                             f"and {self.basis_points!r}")

    @property
    def figures(self) -> str:
        """``abe ∼ ABE``: the figure on the plan and the figure on the mechanism it is similar to."""
        return f"{''.join(self.basis)}{self.letter} ∼ {''.join(self.basis_points)}{self.point}"

    @property
    def text(self) -> str:
        """The step's equation as the records write it (``e: abe ∼ ABE (similarity)``)."""
        if self.basis:
            return f"{self.letter}: {self.figures} (similarity)"
        return f"{self.letter}: link {self.link} turns with link {self.turns_with} (similarity)"


@dataclass(frozen=True)
class Step:
    """One vector equation solved on the plan.

    ``equation`` is written as the textbook writes it (``vB = vA + vBA =
    vC + vBC``); ``vectors`` are the known vectors laid off and the unknown
    ones found; ``lines`` the lines of action drawn; ``fixes`` the plan points
    the step fixes; ``crossing_deg`` the angle at which its lines crossed.
    A step that places a point by the similarity theorem lays off nothing and
    says how in ``similarity`` (its ``equation`` is ``similarity.text``).
    ``translating`` is the link whose translation on the frame's guide
    makes the equation hold (``aB = aA4``: link 4 does not turn).
    """

    equation: str
    vectors: tuple[LaidVector, ...]
    lines: tuple[DrawnLine, ...] = ()
    fixes: tuple[str, ...] = ()
    crossing_deg: float | None = None
    similarity: Similarity | None = None
    translating: int | None = None


@dataclass(frozen=True)
class Plan:
    """A velocity or acceleration plan of one position, as constructed.

    ``points`` are in SI units (m/s or m/s²) relative to the pole; divided by
    ``scale`` they are the millimetres of the drawing (:meth:`mm`).
    ``images`` maps each mechanism point to its plan letter; ``rates`` holds
    the angular velocity (velocity plan) or angular acceleration
    (acceleration plan) of each link as read off the plan, ccw positive;
    ``slide_ends`` are each slider's plan letters, from and to, of the vector that lays off its velocity
    (or acceleration) relative to its guide (:attr:`sliding`): the letters tell two equal slides apart,
    both zero at an extreme;
    ``members`` lists each link's points on the plan as (position, letter);
    ``auxiliary`` the construction's own points of the mechanism that no
    scene names (Assur's special point ``Σ6`` of a triad), where they lie (m).
    """

    kind: str
    scale: float
    points: Mapping[str, complex]
    steps: tuple[Step, ...]
    images: Mapping[str, str]
    rates: Mapping[int, float]
    slide_ends: Mapping[int, tuple[str, str]]
    members: Mapping[int, tuple[tuple[complex, str], ...]] = field(default_factory=dict)
    auxiliary: Mapping[str, complex] = field(default_factory=dict)

    def __repr__(self) -> str:
        # The dataclass's own repr printed every step of the construction (some 3 500 characters).
        return f"<Plan ({self.kind}) of points {', '.join(self.points)} at μ = {self.scale:g} per mm>"

    def mm(self, letter: str) -> complex:
        return self.points[letter] / self.scale

    @property
    def sliding(self) -> dict[int, complex]:
        """Each slider's velocity (or acceleration) relative to its guide, SI: its slide's vector on the plan."""
        return {slider: self.points[end] - self.points[start] for slider, (start, end) in self.slide_ends.items()}

    def value(self, point: str) -> complex:
        """The absolute velocity or acceleration of a mechanism point, SI."""
        return self.points[self.images[point]]


def coriolis(omega: float, relative: complex) -> complex:
    """2·ω × v_rel: the relative velocity turned by 90° in the sense of ω, 2|ω| times as long."""
    return turned(2.0 * abs(omega) * relative, omega)


@dataclass
class Builder:
    """The drawing board while a plan is being built (mutable only during construction).

    ``positions`` are the mechanism's points at the instant (m); plan points
    are kept in SI.  Groups call :meth:`lay`, :meth:`cross`, :meth:`step` and
    :meth:`on_link` as they construct.
    """

    kind: str
    mechanism: Mechanism
    positions: Mapping[str, complex]
    directions: Mapping[int, complex]
    size: float
    points: dict[str, complex] = field(default_factory=lambda: {"p": 0j})
    steps: list[Step] = field(default_factory=list)
    images: dict[str, str] = field(default_factory=dict)
    link_images: dict[int, list[tuple[complex, str]]] = field(default_factory=dict)
    turns_with: dict[int, int] = field(default_factory=dict)
    slide_ends: dict[int, tuple[str, str]] = field(default_factory=dict)
    auxiliary: dict[str, complex] = field(default_factory=dict)
    # The Coriolis parts, by the letters of their ends (k, k5), laid off against 2·ω × v_rel, as a student who turned
    # v_rel the wrong way did: the plan whose lengths such a student's readings are (:mod:`graphplan.misreadings`).
    coriolis_reversed: frozenset[str] = frozenset()
    coriolis_laid: list[str] = field(default_factory=list)

    def image(self, point: str) -> complex:
        return self.points[self.images[point]]

    def lay_coriolis(self, letter: str, start: str, omega: float, relative: complex) -> str:
        """The end of the Coriolis part 2·ω × v_rel (:func:`coriolis`) laid off from the plan's point ``start``,
        marked ``letter``; laid off against it where the board reverses that letter's."""
        laid = coriolis(omega, relative)
        self.coriolis_laid.append(letter)
        return self.mark(letter, self.points[start] + (-laid if letter in self.coriolis_reversed else laid))

    def guide_line(self, guide) -> tuple[complex, complex, int]:
        """A guide at this instant: a point of it (m), its unit direction, the link that carries it."""
        return guide_at(self.mechanism, self.positions, self.directions, guide)

    def guide_direction(self, guide) -> complex:
        return self.guide_line(guide)[1]

    def fix(self, point: str, value: complex, letter: str | None = None) -> str:
        """Put the image of mechanism ``point`` on the plan."""
        letter = letter or image_name(point)
        self.points[letter] = value
        self.images[point] = letter
        return letter

    def slides(self, slider: int, start: str, end: str) -> None:
        """Record that link ``slider`` moves along its guide as the plan's vector from ``start`` to ``end``."""
        self.slide_ends[slider] = (start, end)

    def mark(self, letter: str, value: complex) -> str:
        """An auxiliary point of the plan (the end of a normal component ``n3``, of a Coriolis one ``k``)."""
        self.points[letter] = value
        return letter

    def cross(self, first: Line, second: Line) -> tuple[complex, float]:
        """The crossing of two lines of action, and the angle they cross at.

        The lines are drawn out to a multiple of the plan's own extent (an
        acceleration plan may measure thousands of m/s² on a mechanism of a
        few decimetres), so that two lines that are not parallel always meet.
        """
        # The plan's own extent, not the mechanism's metres: a slow crank's plan may measure 1e-7 m/s².
        extent = max([abs(first.through), abs(second.through), *(abs(z) for z in self.points.values())])
        return cross_lines(first, second, extent), crossing_angle_deg(first, second)

    def widest(self, link: int):
        """The two images of ``link`` farthest apart on the mechanism, or None without two distinct ones."""
        known = self.link_images.get(link, [])
        pairs = [(a, b) for i, a in enumerate(known) for b in known[i + 1:] if a[0] != b[0]]
        return max(pairs, key=lambda pair: abs(pair[0][0] - pair[1][0])) if pairs else None

    def figure_ratio(self, link: int) -> complex:
        """(q − p)/(Q − P) for two points P, Q of ``link`` and their images p, q.

        The image of a link is its figure turned and scaled: iω on a velocity
        plan, iε − ω² on an acceleration plan.  A link with one point on the
        plan takes the ratio of the link it turns with; with none it
        translates, and the ratio is 0.
        """
        if link == self.mechanism.scene.frame_link:
            return 0j
        pair = self.widest(link)
        if pair is not None:
            (pa, la), (pb, lb) = pair
            return (self.points[lb] - self.points[la]) / (pb - pa)
        if link in self.turns_with:
            return self.figure_ratio(self.turns_with[link])
        return 0j

    def image_on(self, link: int, position: complex) -> complex:
        """The image of the point of ``link`` at ``position``, by the similarity theorem."""
        if link == self.mechanism.scene.frame_link:
            return 0j
        pair = self.widest(link)
        if pair is not None:
            (pa, la), (pb, lb) = pair
            return similar_point(self.points[la], self.points[lb], pa, pb, position)
        (pa, la), *_ = self.link_images[link]
        return self.points[la] + self.figure_ratio(link) * (position - pa)

    def on_link(self, link: int, position: complex, letter: str) -> None:
        """Record that the plan point ``letter`` is the image of the link's point at ``position``."""
        self.link_images.setdefault(link, []).append((position, letter))

    def step(self, step: Step) -> None:
        self.steps.append(step)

    def similarity_step(self, letter: str, link: int, point: str, pair, from_pole: bool = False) -> None:
        """Record that ``letter`` was placed by similarity from the images ``pair`` of ``link`` (``widest``);
        ``from_pole`` lays its absolute vector off too, for a point that is no image of the mechanism's own
        (a guide's point under a slider), whose vector the plan would otherwise leave out."""
        if pair is not None:
            (pa, la), (pb, lb) = pair
            similarity = Similarity(letter, point, link, (la, lb), (self.name_at(la, pa), self.name_at(lb, pb)))
        else:
            similarity = Similarity(letter, point, link, turns_with=self.turns_with.get(link))
        symbol = "v" if self.kind == "velocity" else "a"
        vectors = (LaidVector("p", letter, f"{symbol}{point}"),) if from_pole else ()
        self.step(Step(equation=similarity.text, vectors=vectors, fixes=(letter,), similarity=similarity))

    def name_at(self, letter: str, position: complex) -> str:
        """The mechanism's name of the point at ``position`` whose image is ``letter`` (``A4`` for ``a4``)."""
        for name, image in self.images.items():
            if image == letter and self.positions.get(name) == position:
                return name
        for name, where in self.auxiliary.items():
            if where == position and image_name(name) == letter:
                return name
        return letter.upper()


def guide_at(mechanism: Mechanism, positions: Mapping[str, complex], directions: Mapping[int, complex],
             guide) -> tuple[complex, complex, int]:
    """A guide at one instant: a point of it (m), its unit direction, the link that carries it."""
    scene = mechanism.scene
    if guide.line is not None:
        guide = scene.frame_lines[guide.line]
    link = scene.frame_link if guide.link is None else guide.link
    through = positions[guide.through] if isinstance(guide.through, str) else complex(*guide.through)
    direction = directions.get(link, 1 + 0j) * complex(math.cos(guide.angle), math.sin(guide.angle))
    return through, direction, link


def velocity_plan(mechanism: Mechanism, positions: Mapping[str, complex], directions: Mapping[int, complex],
                  scale: float | None = None) -> Plan:
    """The velocity plan of the instant whose point positions are ``positions`` (m).

    ``directions`` are the unit vectors of the links' reference lines at the
    instant (the drawing of the mechanism shows them), which guides on moving
    links need.
    """
    board = Builder("velocity", mechanism, positions, directions, _size(positions))
    _frame_at_pole(board, mechanism)
    for unit in mechanism.units:
        unit.solver.construct_velocity(board)  # type: ignore[union-attr]
        _place_named(board, mechanism, unit.points)
    rates = _read_rates(board, mechanism)
    return _finish(board, rates, scale, mechanism, pole_mm_key="velocity")


def acceleration_plan(mechanism: Mechanism, positions: Mapping[str, complex], directions: Mapping[int, complex],
                      velocities: Plan, scale: float | None = None,
                      coriolis_reversed: Collection[str] = frozenset()) -> Plan:
    """The acceleration plan of the same instant, using ω and relative velocities read off ``velocities``; with
    ``coriolis_reversed`` (the letters of Coriolis parts' ends), the plan of a hand that laid those parts off the
    wrong way."""
    # A string would be taken letter by letter ("k5" as k and 5), True as no collection at all.
    if isinstance(coriolis_reversed, str | bool) or not isinstance(coriolis_reversed, Collection):
        raise TypeError(f"coriolis_reversed is a collection of the letters of Coriolis parts' ends, such as "
                        f"['k'] or ['k3', 'k5'] (got {coriolis_reversed!r})")
    board = Builder("acceleration", mechanism, positions, directions, _size(positions),
                    coriolis_reversed=frozenset(coriolis_reversed))
    _frame_at_pole(board, mechanism)
    for unit in mechanism.units:
        unit.solver.construct_acceleration(board, velocities)  # type: ignore[union-attr]
        _place_named(board, mechanism, unit.points)
    if unknown := sorted(board.coriolis_reversed.difference(board.coriolis_laid)):
        raise ValueError(f"coriolis_reversed: {', '.join(unknown)} ends no Coriolis part of the plan, whose parts end "
                         f"at {', '.join(board.coriolis_laid) or 'none'}")
    rates = _read_rates(board, mechanism)
    return _finish(board, rates, scale, mechanism, pole_mm_key="acceleration")


def _frame_at_pole(board: Builder, mechanism: Mechanism) -> None:
    """The frame's points stand still: their images are all at the pole."""
    for name, position in mechanism.scene.frame_points.items():
        board.images[name] = "p"
        board.on_link(mechanism.scene.frame_link, position, "p")


def _size(positions: Mapping[str, complex]) -> float:
    values = list(positions.values())
    return max(max(abs(a - b) for a in values for b in values), 1e-9)


def _place_named(board: Builder, mechanism: Mechanism, specs) -> None:
    """Images of named points by the similarity theorem, from the images already on their link."""
    for spec in specs:
        position = board.positions[spec.name]
        if spec.link == mechanism.scene.frame_link:
            board.images[spec.name] = "p"
            continue
        pair = board.widest(spec.link)
        letter = board.fix(spec.name, board.image_on(spec.link, position))
        board.on_link(spec.link, position, letter)
        board.similarity_step(letter, spec.link, spec.name, pair)


def _read_rates(board: Builder, mechanism: Mechanism) -> dict[int, float]:
    """ω (velocity plan) or ε (acceleration plan) of every moving link, read off its image.

    On a velocity plan qp = ω × PQ, so ω = (PQ × pq)/PQ²; on an acceleration
    plan the tangential part gives ε the same way.
    """
    return {link: board.figure_ratio(link).imag for link in mechanism.moving_links}


def _finish(board: Builder, rates: dict[int, float], scale: float | None, mechanism: Mechanism,
            pole_mm_key: str) -> Plan:
    drawing = mechanism.scene.drawing
    pole_mm = drawing.velocity_pole if pole_mm_key == "velocity" else drawing.acceleration_pole
    given = drawing.velocity_scale if pole_mm_key == "velocity" else drawing.acceleration_scale
    if scale is None:
        scale = given
    if scale is None and pole_mm is not None and abs(board.image(mechanism.driver.joint)) > 0:
        scale = abs(board.image(mechanism.driver.joint)) / pole_mm
    plan = Plan(kind=board.kind, scale=1.0, points=dict(board.points), steps=tuple(board.steps),
                images=dict(board.images), rates=rates, slide_ends=dict(board.slide_ends),
                members={link: tuple(dict.fromkeys(known)) for link, known in board.link_images.items()},
                auxiliary=dict(board.auxiliary))
    if scale is None:
        scale = standard_scale(spread(plan) / PLAN_FIELD_MM)
    return replace(plan, scale=scale)


def spread(plan: Plan) -> float:
    """The largest distance between two points of the plan (SI), never quite zero: what its scale must fit."""
    return max(max(abs(a - b) for a in plan.points.values() for b in plan.points.values()), 1e-300)


__all__ = [
    "SHALLOW_CROSSING_DEG",
    "Builder",
    "DrawnLine",
    "LaidVector",
    "LineKind",
    "LineMeaning",
    "ParallelLinesError",
    "Plan",
    "Similarity",
    "Step",
    "acceleration_plan",
    "guide_at",
    "image_name",
    "spread",
    "velocity_plan",
]
