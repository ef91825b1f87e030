"""Zhukovsky's lever: the balancing moment from the velocity plan turned through 90°.

Every load is applied at the image of its point on the velocity plan turned
clockwise by 90°, and the plan, taken as a rigid lever pivoted at the pole,
is put in equilibrium.  Turned so, a force F at the image of a point moving
with v has the moment ``F·v`` about the pole: the lever is the power balance
drawn.  A moment M on a link becomes a couple of forces ``M/l`` across two of
its points, whose lever moment is ``M·ω``.  The balancing moment is applied
as a force at the image of the crank's joint, across the crank.

Only the velocity plan as constructed and the loads of the instant enter:
no reaction, no analytic value.  A load on the frame does no work and is
left off; a force on a guide at a slider's joint acts at the image of the
guide's own point there (``a4``, not ``a``), so that the friction of a
sliding pair enters with the relative velocity, as its power loss does.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from .forces import TERM_ROUNDING, Load, negligible
from .geometry import perpendicular_foot
from .kinematics import cross
from .mechanism import Mechanism
from .plans import Plan

# The balancing force on the lever, at the image of the driver's joint, and its arm's name: keys, which a locale spells
# (Fу and hу in Russian) with load_symbol.
BALANCING_FORCE = "Fb"
BALANCING_ARM = "hb"


@dataclass(frozen=True)
class LeverTerm:
    """A force on the lever at the plan point ``image`` (turned) and its moment about the pole.

    ``arm`` is the perpendicular from the pole to the force's line on the
    turned plan, in the plan's own units (m/s); ``moment`` is in W.  A
    displaced force acts at the image of its own point: ``shift`` (m/s, on
    the plan before it is turned) from ``image``, the image of its link's point.  A moment on a block,
    which has no two points of its own on the plan, is no force: no ``image``, its ``moment`` M·ω of
    ``link``'s ω.
    """

    name: str
    image: str
    force: complex
    arm: float
    moment: float
    shift: complex = 0j
    link: int | None = None


@dataclass(frozen=True)
class Lever:
    """The lever of one position: its terms, the balancing force at the driver's image, the balancing load."""

    terms: tuple[LeverTerm, ...]
    balancing_force: complex
    balancing_image: str
    balancing: float

    def stands(self, term: LeverTerm) -> bool:
        """Whether ``term`` stands in the lever's equation: its moment is more than the rounding beside the largest
        (the balancing force's among them), however short its arm on the drawing."""
        largest = max([abs(other.moment) for other in self.terms] + [abs(sum(other.moment for other in self.terms))])
        return abs(term.moment) > TERM_ROUNDING * largest

    def standing(self, velocity: Plan) -> frozenset[str]:
        """The names of the terms that stand in ΣMp as the lever of ``velocity`` is drawn and worked: those that stand
        (:meth:`stands`) and are more than the rounding beside the loads' powers at the plan's fastest point.

        A term's power is rounding where its point stands still or moves square to it: at a Scotch yoke's dead
        centre every one is, and the lever wrote h1 = 0.000000000000006661 mm and Mb = −0.00000000000001040 N·m
        where the polygons find Mb = 0.
        """
        reach = (max((abs(value) for value in velocity.points.values()), default=0.0)
                 * max((abs(term.force) for term in self.terms), default=0.0))
        return frozenset(term.name for term in self.terms
                         if self.stands(term) and abs(term.moment) > TERM_ROUNDING * reach)

    @property
    def forces(self) -> tuple[tuple[str, str, complex, complex], ...]:
        """Each force on the lever as (name, image, force, shift in m/s on the plan before it is turned), the
        balancing force Fb last: the loads' forces, a block's moment (no force) and a nought force left out."""
        loads = tuple((term.name, term.image, term.force, term.shift) for term in self.terms
                      if term.image and term.force != 0)
        return (*loads, (BALANCING_FORCE, self.balancing_image, self.balancing_force, 0j))

    def arm_names(self, velocity: Plan, drawn_at: float, precision: float,
                  standing: frozenset[str] | None = None) -> dict[str, str]:
        """The name of the arm of each force the lever of ``velocity`` names one for, drawn at μV ``drawn_at``
        ((m/s)/mm) to the drafting ``precision`` (mm): h1, h2, … in the order of :attr:`forces`, ``hb`` the balancing
        force's, one name for the forces whose lines are one line (:func:`shared_arms`), ``hb`` where Fb is among
        them.  ``hb`` is a key: the caller spells it as its locale writes it (``load_symbol``: hу in Russian).

        Named are Fb and the forces whose terms stand in ΣMp (:meth:`standing`, or ``standing`` where the caller has
        worked it out for ``velocity`` already) and that are no rounding error beside the others
        (:func:`~graphplan.forces.negligible`: the lever draws no arrow for one).  The force sheet letters
        the lever's arms by these names and the note writes each load's arm with them, so that the note's h2 is the
        sheet's; the scale is the one the lever is drawn at, since the drafting precision there decides which lines
        are one.
        """
        forces = self.forces
        standing = (self.standing(velocity) if standing is None else standing) | {BALANCING_FORCE}
        named = [force for force in forces if force[0] in standing
                 and not negligible(force[2], [other for _, _, other, _ in forces])]
        names: dict[str, str] = {}
        count = 0
        for gathered in shared_arms(velocity, named, precision * drawn_at):
            if BALANCING_FORCE in gathered:
                arm = BALANCING_ARM
            else:
                count += 1
                arm = f"h{count}"
            names.update(dict.fromkeys(gathered, arm))
        return names

    def difference_percent(self, polygons: float) -> float:
        """(lever − polygons)/polygons · 100: how far the two methods part."""
        return (self.balancing - polygons) / polygons * 100.0 if polygons else 0.0


def arm_foot(velocity: Plan, image: str, force: complex, shift: complex = 0j) -> complex:
    """The foot of the arm from the pole to the line of ``force`` at the image ``image`` (shifted by ``shift``) on the
    turned plan, in the plan's units (m/s): the arm is the segment from the pole to it."""
    return perpendicular_foot(0j, turned(velocity.points[image] + shift), force / abs(force))


def shared_arms(velocity: Plan, loads: Sequence[tuple[str, str, complex, complex]], tolerance: float
                ) -> list[tuple[str, ...]]:
    """The loads of the lever (name, image, force, shift) gathered by their arm: loads whose lines are one line
    (their arms' feet within ``tolerance``, m/s on the plan: the drafting precision at the lever's scale, and
    farther than that from the pole, where a foot fixes the line square to its arm) have one arm, the same
    perpendicular from the pole, which the student draws and names once.  An arm within ``tolerance`` of the pole
    stays each load's own: lines through the pole's neighbourhood may run every way.

    Several couples on one link put their forces at the same two images across it (the inertia moment's and the
    friction moments' at the link's joints), and a crank's couples lie on the balancing force's line: on the friction
    lever three arms of one perpendicular were named h4, h11, h15 at one foot.  Each gathering keeps the loads'
    order, and the gatherings are in the order of their first loads.
    """
    gathered: list[tuple[list[str], complex]] = []  # names, foot
    for name, image, force, shift in loads:
        foot = arm_foot(velocity, image, force, shift)
        for names, first_foot in gathered:
            if abs(foot) > tolerance and abs(first_foot) > tolerance and abs(foot - first_foot) <= tolerance:
                names.append(name)
                break
        else:
            gathered.append(([name], foot))
    return [tuple(names) for names, _ in gathered]


def turned(velocity: complex) -> complex:
    """A velocity plan point after the plan is turned clockwise by 90°."""
    return -1j * velocity


def lever(mechanism: Mechanism, positions: dict[str, complex], velocity: Plan, loads: tuple[Load, ...]) -> Lever:
    """Zhukovsky's lever of the instant whose velocity plan is ``velocity``."""
    terms: list[LeverTerm] = []
    for load in loads:
        if load.link == mechanism.scene.frame_link:
            continue
        if load.is_force:
            image, under = _image_on(velocity, load.link, load.point, positions[load.point])
            # The image of a displaced point by similarity: its velocity relative to the link's point is ω × offset.
            shift = under + (1j * velocity.rates.get(load.link, 0.0) * load.offset if load.offset else 0j)
            terms.append(_term(load.name, image, load.force, velocity.points[image] + shift, shift))
        elif load.moment != 0:
            terms.extend(_couple(load, positions, velocity))
    total = sum(term.moment for term in terms)
    driver = mechanism.driver
    joint = positions[driver.joint]
    if driver.kind == "crank":
        arm = joint - positions[driver.pivot]
        unit_force = 1j * arm / abs(arm) ** 2  # a force across the crank whose moment about its pivot is 1 N·m
    else:
        unit_force = velocity.value(driver.joint) / abs(velocity.value(driver.joint))
        unit_force = unit_force if driver.velocity > 0 else -unit_force  # along the guide's own direction
    unit_moment = cross(turned(velocity.value(driver.joint)), unit_force)
    balancing = -total / unit_moment
    return Lever(tuple(terms), balancing * unit_force, velocity.images[driver.joint], float(balancing))


def _image_on(velocity: Plan, link: int, point: str, where: complex) -> tuple[str, complex]:
    """The image of the point of ``link`` at ``where``, as a plan point and a shift from it (m/s).

    The point's own image, unless another link carries the point: then
    ``link``'s own image there (the guide's ``a4`` under the slider's joint
    ``A``) or, where the plan has none (a slot on a rocker, ``b4`` under the
    block's ``B``), the nearest of ``link``'s images shifted by ω × the
    distance, as the similarity theorem would place ``b4``.
    """
    own = velocity.images[point]
    members = velocity.members.get(link, ())
    if not members or any(letter == own for _, letter in members):
        return own, 0j
    nearest, letter = min(members, key=lambda member: abs(member[0] - where))
    if abs(nearest - where) <= 1e-9 * max(abs(where), 1.0):
        return letter, 0j
    return letter, 1j * velocity.rates.get(link, 0.0) * (where - nearest)


def _term(name: str, image: str, force: complex, at: complex, shift: complex = 0j) -> LeverTerm:
    moment = float(cross(turned(at), force))
    arm = abs(moment) / abs(force) if force else 0.0
    return LeverTerm(name, image, complex(force), arm, moment, complex(shift))


def _couple(load: Load, positions: dict[str, complex], velocity: Plan) -> list[LeverTerm]:
    """The moment as a couple across the two points of its link farthest apart on the drawing.

    A link with fewer than two points of its own on the plan (a slider
    block) takes the ``M·ω`` rule instead, with ω read off the plan.
    """
    named = list(velocity.members.get(load.link, ()))
    pairs = [(a, b) for i, a in enumerate(named) for b in named[i + 1:] if a[0] != b[0]]
    if not pairs:
        return [LeverTerm(load.name, "", 0j, 0.0, float(load.moment * velocity.rates.get(load.link, 0.0)),
                          link=load.link)]
    (first, first_letter), (second, second_letter) = max(pairs, key=lambda pair: abs(pair[0][0] - pair[1][0]))
    across = 1j * (second - first)
    force = load.moment * across / abs(second - first) ** 2
    return [_term(f"{load.name}′", second_letter, force, velocity.points[second_letter]),
            _term(f"{load.name}″", first_letter, -force, velocity.points[first_letter])]


__all__ = ["BALANCING_ARM", "BALANCING_FORCE", "Lever", "LeverTerm", "arm_foot", "lever", "shared_arms", "turned"]
