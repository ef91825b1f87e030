"""The mechanism: frame, driver and groups in structure order, with every name checked.

:func:`build` turns a :class:`~graphplan.scene.Scene` into a
:class:`Mechanism` after checking that the names refer to each other: every
joint a group needs is known by then, every link of a group is new, every
guide, point, centre and load names something that exists.  The mechanism
also knows, for every link, which points are fixed on it and which slide on
it, which the placement of named points needs.
"""

from __future__ import annotations

import dataclasses
import itertools
import math
from collections.abc import Iterator, Mapping
from dataclasses import dataclass
from types import MappingProxyType

from .errors import GraphplanError, SceneError, as_written, listed
from .groups import Driver, Group, Guide
from .groups.sliding import guide_link
from .lookalikes import construction_letter_clash, contrast, difference, lookalike_hint, plain, plan_letter, twin
from .reader import join_path, radians_within_a_turn, suggestion
from .scene import PointSpec, Scene, not_a_scene

_ROMAN = {1: "I", 2: "II", 3: "III"}


@dataclass(frozen=True)
class Unit:
    """One step of the solution order: the driver, a group, or named points placed after it."""

    solver: Driver | Group
    points: tuple[PointSpec, ...]


@dataclass(frozen=True)
class Mechanism:
    """A checked mechanism, ready to be solved."""

    scene: Scene
    units: tuple[Unit, ...]
    fixed_on: Mapping[int, frozenset[str]]
    sliding_on: Mapping[int, Mapping[str, complex]]
    translating: frozenset[int]

    def __repr__(self) -> str:
        # The dataclass's own repr printed the whole scene, some 3 000 characters.
        return (f"<Mechanism of {self.scene.title!r}: driver link {self.driver.link}, groups "
                f"{', '.join(group.label for group in self.groups) or 'none'}>")

    @property
    def driver(self) -> Driver:
        return self.units[0].solver  # type: ignore[return-value]

    @property
    def groups(self) -> tuple[Group, ...]:
        return tuple(unit.solver for unit in self.units[1:])  # type: ignore[misc]

    @property
    def moving_links(self) -> tuple[int, ...]:
        numbers = [self.driver.link]
        for group in self.groups:
            numbers.extend(group.links)
        return tuple(numbers)

    @property
    def degrees_of_freedom(self) -> tuple[int, int, int]:
        """Chebyshev's formula W = 3n − 2p5 − p4 as (n, p5, W): every pair here is a lower pair."""
        moving = len(self.moving_links)
        lower_pairs = 1 + sum(group.pair_count for group in self.groups)
        return moving, lower_pairs, 3 * moving - 2 * lower_pairs

    @property
    def structure(self) -> str:
        """The structure formula, ``I(1,2) → II2(3,4)``: class, order, links of each group.

        Each arrow leads to a group from a unit it is attached to, so that a teacher reads the order the groups
        attach in: a group not attached to the one written before it (two dyads both hung on the crank) starts
        a branch from the latest unit it is attached to, ``I(1,2) → II2(3,4); I(1,2) → II2(5,6)``.
        """
        labels = [f"I({self.scene.frame_link},{self.driver.link})"]
        labels += [f"{_ROMAN[group.klass]}{group.order}({','.join(map(str, group.links))})" for group in self.groups]
        formula = labels[0]
        for index, attached in enumerate(self.attached_to, start=1):
            if index - 1 not in attached:
                formula += f"; {labels[max(attached, default=0)]}"
            formula += f" → {labels[index]}"
        return formula

    @property
    def attached_to(self) -> tuple[frozenset[int], ...]:
        """For each group, the units (0 the driver, k the k-th group) whose links its outer pairs join, the frame
        aside: an outer joint is on the link that first carried it, a guide on its own link."""
        frame = self.scene.frame_link
        unit_of: dict[int, int] = {}
        attached = []
        for index, (unit, carriers) in enumerate(self._carriers_at_each_unit()):
            solver = unit.solver
            if index > 0:
                links = {carriers[name] for name in solver.known_joints()}
                links.update(guide_link(self, guide) for guide in solver.guides())
                attached.append(frozenset(unit_of[link] for link in links if link != frame))
            unit_of.update(dict.fromkeys((solver.link,) if index == 0 else solver.links, index))  # type: ignore[union-attr]
        return tuple(attached)

    def _carriers_at_each_unit(self) -> Iterator[tuple[Unit, Mapping[str, int]]]:
        """Each unit in solution order with the link that carries each point known before it: the first link that
        carried it (a pin at a compound hinge is taken to belong to that link).  The mapping is read as it is
        handed out; it grows by the unit's points after."""
        carriers: dict[str, int] = dict.fromkeys(self.scene.frame_points, self.scene.frame_link)
        for unit in self.units:
            yield unit, carriers
            for number, names in unit.solver.fixed_points().items():
                for name in names:
                    carriers.setdefault(name, number)
            for spec in unit.points:
                carriers.setdefault(spec.name, spec.link)

    @property
    def revolutes(self) -> tuple[tuple[str, int, int], ...]:
        """Every turning pair as (joint, earlier link, later link), in solution order.

        An outer joint joins its group to the first link that carried it: at a
        compound hinge the pin is taken to belong to that link.
        """
        return tuple((joint, carriers[joint] if other is None else other, link)
                     for unit, carriers in self._carriers_at_each_unit()
                     for joint, link, other in unit.solver.revolutes())

    def point_names(self) -> tuple[str, ...]:
        """Every point with a motion, in solution order: frame points first."""
        names = list(self.scene.frame_points)
        for unit in self.units:
            names.extend(unit.solver.new_joints())
            names.extend(spec.name for spec in unit.points)
        return tuple(names)


def build(scene: Scene) -> Mechanism:
    """Check the names of ``scene`` against each other and order the solution."""
    if not isinstance(scene, Scene):  # a path or a dict failed deep inside, on its missing .driver
        raise not_a_scene("build", scene)
    if scene.driver is None:
        raise SceneError("driver", "is required but missing: this scene has no mechanism ([frame] and [driver])")
    frame = scene.frame_link
    known_points = set(scene.frame_points)
    known_links = {frame}
    fixed_on: dict[int, set[str]] = {frame: set(scene.frame_points)}
    # The link each known point is pinned to where a group joins it: the first link that carried it.
    carried_by: dict[str, int] = dict.fromkeys(scene.frame_points, frame)
    sliding_on: dict[int, dict[str, complex]] = {}
    under_pins: dict[str, tuple[str, int]] = {}  # a link's point under a pin (A4), with the pin and the link
    pending = list(scene.points)
    named_at = _check_point_names(scene)
    units = []
    solvers: list[Driver | Group] = [scene.driver, *scene.groups]
    for index, solver in enumerate(solvers):
        where = solver.where
        links = (solver.link,) if index == 0 else solver.links  # type: ignore[union-attr]
        for number in links:
            if number in known_links:
                raise SceneError(f"{where}.link" if index == 0 else f"{where}.links",
                                 f"link {number} already belongs to {'the frame' if number == frame else 'an earlier group'}; a group's links are new")
        if index == 0 and scene.driver.kind == "crank" and scene.driver.pivot not in scene.frame_points:
            raise SceneError(f"{where}.pivot", f"must be a point of [frame] points: {_known(scene.frame_points)}",
                             scene.driver.pivot, hint=lookalike_hint(scene.driver.pivot, scene.frame_points))
        for name in solver.known_joints():
            if name not in known_points:
                # A named point of a link already found that could not be placed: its own from or toward is the slip.
                unplaced = [spec for spec in pending if spec.link in known_links]
                if any(spec.name == name for spec in unplaced):
                    unplaced.sort(key=lambda spec: spec.name != name)
                    raise _unplaceable(unplaced, known_links, fixed_on, sliding_on, frame, under_pins, scene)
                raise _unknown_joint(solver, name, known_points, named_at)
        if index == 0 and scene.driver.kind == "slider" and not on_frame(scene, scene.driver.guide):
            raise SceneError(f"{where}.guide", "a driving slider must slide on a frame guide")
        for guide in solver.guides():
            _check_guide(scene, guide, known_links, fixed_on)
        if index > 0:
            _check_moves(scene, solver, carried_by)  # type: ignore[arg-type]
        for name in solver.new_joints():
            if name in known_points:
                raise SceneError(*_clash(solver, name))
            known_points.add(name)
        known_links.update(links)
        for number, names in solver.fixed_points().items():
            fixed_on.setdefault(number, set()).update(names)
            for name in names:
                carried_by.setdefault(name, number)
        for number, slides in solver.sliding_points().items():
            sliding_on.setdefault(number, {}).update(slides)
        under_pins.update({name: (pin, link) for name, pin, _, link in getattr(solver, "coincident_points", tuple)()})
        placed, pending = _place_points(pending, known_links, fixed_on, sliding_on, known_points)
        for spec in placed:
            carried_by.setdefault(spec.name, spec.link)
        units.append(Unit(solver, placed))
    if pending:
        raise _unplaceable(pending, known_links, fixed_on, sliding_on, frame, under_pins, scene)
    _refuse_unused_frame_lines(scene, solvers)
    mechanism = Mechanism(
        scene=scene,
        units=tuple(units),
        fixed_on=MappingProxyType({k: frozenset(v) for k, v in fixed_on.items()}),
        sliding_on=MappingProxyType({k: MappingProxyType(v) for k, v in sliding_on.items()}),
        translating=frozenset(_translating_links(scene)),
    )
    _check_references(mechanism, known_points, known_links)
    return mechanism


def _check_moves(scene: Scene, group: Group, carried_by: dict[str, int]) -> None:
    """Refuse a group whose outer joints and guides are all on one link: an Assur group has no freedom of its
    own, so joined to the frame alone it stands still, and joined to one moving link alone it moves with that link
    as one rigid body (a truss), no part of the mechanism's motion and no Assur group (a joint's name mistyped for
    a frame point's, or for another point of the crank's, does this)."""
    frame = scene.frame_link
    joints, guides = group.known_joints(), group.guides()
    links = {carried_by[name] for name in joints} | {frame if on_frame(scene, g) else g.link for g in guides}
    if len(links) != 1:
        return
    (link,) = links
    on = "the frame" if link == frame else f"link {link}"
    parts = []
    if joints:
        one, many = ("frame point", "frame points") if link == frame else (f"point of link {link}",
                                                                           f"points of link {link}")
        parts.append(f"its outer joints {', '.join(joints)} are {many}" if len(joints) > 1 else
                     f"its outer joint {joints[0]} is a {one}")
    if guides:
        parts.append(f"its guides are on {on}" if len(guides) > 1 else f"its guide is on {on}")
    what = " and ".join(parts)
    if link == frame:
        why = ("the group cannot move: join it to the driver or to an earlier group by a joint of theirs or a named "
               "point of one of their links")
    else:
        why = (f"the group moves with link {link} as one rigid body, no Assur group: join an outer joint or a guide "
               f"of it to another link (the frame, or another link of the driver or of an earlier group)")
    raise SceneError(f"{group.where}.joints" if joints else f"{group.where}.guides",
                     f"joins {on} alone ({what}), so {why}", list(joints))


def _joint_where(solver: Driver | Group, name: str) -> str:
    """The key that names a joint the solver needs: ``driver.pivot``, ``groups[1].joints[0]``."""
    if not hasattr(solver, "joints"):
        return f"{solver.where}.pivot"
    return f"{solver.where}.joints[{solver.joints.index(name)}]"  # type: ignore[union-attr]


def _clash(solver: Driver | Group, name: str) -> tuple[str, str]:
    """Where and why a joint the solver finds has a name already taken."""
    if not hasattr(solver, "joints"):
        return f"{solver.where}.joint", f"{name!r} is already a frame point; the driver's joint is new"
    if name not in solver.joints:  # type: ignore[union-attr]
        first, lever = solver.joints[0], solver.links[1]  # type: ignore[union-attr]
        return (f"{solver.where}.joints",
                (f"graphplan names the point of lever {lever} that coincides with {first} {name!r}, "
                 f"but {name!r} is already a point; rename that point"))
    return (f"{solver.where}.joints[{solver.joints.index(name)}]",  # type: ignore[union-attr]
            f"{name!r} is already a known point; a group's inner joint is new")


def _known(names) -> str:
    names = list(names)
    return ", ".join(str(n) for n in names) if names else "none"


def _unknown_joint(solver: Driver | Group, name: str, known: set[str], named_at: dict[str, str]) -> SceneError:
    """Why a joint the solver needs is not known by then.  Where a known point looks the same in other
    characters, the slip is the one not in ASCII: a group's Latin A joined to the driver's Cyrillic А is told at
    the driver, where the Cyrillic letter was typed."""
    import difflib
    where = _joint_where(solver, name)
    meant = twin(name, known)
    if meant is not None and name.isascii():
        return SceneError(named_at[meant], f"{meant!r} is not the {name!r} that {where} joins to; "
                          f"{difference(meant, name)}")
    if meant is not None:
        return SceneError(where, f"{name!r} is not known at this stage{lookalike_hint(name, known)}")
    # A one-letter name is no close match of another to difflib, but a joint typed in the other case is a slip.
    close = [other for other in sorted(known) if other.casefold() == name.casefold()] or difflib.get_close_matches(
        name, sorted(known), n=1, cutoff=0.5)
    hint = f"; did you mean {close[0]!r}?" if close else _joints_in_place(solver, known)
    return SceneError(where, f"{name!r} is not known at this stage: it must be a frame point, a joint of the driver "
                             f"or of an earlier group, or a named point of a link already found{hint}")


def _joints_in_place(solver: Driver | Group, known: set[str]) -> str:
    """Where two of a group's joints typed in each other's places leave it joined to a point it places itself (an
    RRR's ["B", "A", "C"]), the two swapped back: the order that joins it to known points alone."""
    if not hasattr(solver, "joints"):
        return ""
    for _, in_place in _swapped(solver, "joints"):
        if set(in_place.known_joints()) <= known:
            return (f"; its joints typed in each other's places? {solver.where}.joints = "
                    f"{as_written(list(in_place.joints))} joins it to {listed(in_place.known_joints())} and places "
                    f"{listed(in_place.new_joints())}")
    return ""


def _swapped(group: Group, key: str) -> Iterator[tuple[set, Group]]:
    """The group with two of its ``key`` (``joints``, ``links``) in each other's places, each swap in turn, with the
    two: the orders a refusal tries for the one that a slip of the fingers meant."""
    values = getattr(group, key)
    for i, j in itertools.combinations(range(len(values)), 2):
        swapped = list(values)
        swapped[i], swapped[j] = values[j], values[i]
        try:
            in_place = dataclasses.replace(group, **{key: tuple(swapped)})
        except (GraphplanError, ValueError):
            continue
        yield {values[i], values[j]}, in_place


def _check_point_names(scene: Scene) -> dict[str, str]:
    """Every point the scene names (frame points, joints, [points]) by the key that names it, each name once and
    no two that look the same on screen: the sheets would letter a Cyrillic С and the Latin C both C."""
    named_at = {name: f"frame.points.{name}" for name in scene.frame_points}
    for solver in (scene.driver, *scene.groups):
        for name in solver.new_joints():
            named_at.setdefault(name, _new_joint_where(solver, name))
    for spec in scene.points:
        if spec.name in named_at:
            raise _named_twice(scene, spec.name, spec.where, named_at)
        named_at[spec.name] = spec.where
    seen: dict[str, str] = {}
    for name, where in named_at.items():
        _refuse_markup(name, where)
        other = seen.setdefault(plain(name), name)
        if other != name:
            raise SceneError(where, f"{name!r} looks the same as the point {other!r} of "
                             f"{named_at[other]}, and the drawings would letter both alike; "
                             f"{contrast(name, other)}: name the two apart")
    _check_plan_letters(scene, named_at)
    return named_at


def _named_twice(scene: Scene, name: str, where: str, named_at: dict[str, str]) -> SceneError:
    """A named point given a frame point's or a joint's name, told with the key that names it first; where a group
    places the joint and joins to a point that nothing places, as a group whose joints were typed in each other's
    places does (an RRP's ["F", "E"] for ["E", "F"]), with its joints in their places."""
    if name in scene.frame_points:
        return SceneError(where, f"{name!r} is already a frame point's name ({named_at[name]}): name the point apart")
    placing = next(solver for solver in (scene.driver, *scene.groups) if name in solver.new_joints())
    told = f"{name!r} is already the name of a joint {placing.where} places ({named_at[name]})"
    placed = set(scene.frame_points) | {spec.name for spec in scene.points} | {
        joint for solver in (scene.driver, *scene.groups) for joint in solver.new_joints()}
    unplaced = [joint for joint in placing.known_joints() if joint not in placed]
    in_place = _joints_in_place(placing, placed) if len(unplaced) == 1 else ""
    if not in_place:
        return SceneError(where, f"{told}: name the point apart")
    return SceneError(where, f"{told}, and {unplaced[0]!r}, which {placing.where} joins to, is placed nowhere"
                             f"{in_place}; else name the point apart")


# A point's or a frame line's name enters the note's vector equations, symbols and tables in a hundred places
# (VBA, lAB, R23 beside a point's name; "∥ ram" for a line), all written as Markdown and set from it as HTML, LaTeX
# and Word: one of these marks there sets what follows in italics or as code, or splits a table's row.  Letters of
# any script, digits, primes and the hyphens and dashes of a guide's name (x–x) read as typed.
_MARKUP_IN_NAMES = "*_`|[]<>#&\\^~$%{}"


def _refuse_markup(name: str, where: str, *, line: bool = False) -> None:
    """Refuse a mark of ``_MARKUP_IN_NAMES`` in a name; a space too in a point's, which its symbols run together
    with the names beside it (VBA), where a line's name stands alone ("guide along ram guide" reads)."""
    marks = [mark for mark in dict.fromkeys(name) if mark in _MARKUP_IN_NAMES or (mark.isspace() and not line)]
    if not marks:
        return
    shown = ", ".join("a space" if mark.isspace() else repr(mark) for mark in marks)
    advice = ("name the line with letters, digits, dashes and spaces (x–x, ram)" if line else
              "name points with letters, digits and primes (S4, B′); a digit after the letters is set as a subscript")
    raise SceneError(where, f"the name {name!r} holds {shown}, which the note's equations and tables would read as "
                     f"markup (italics, code, a table's column) or split: {advice}")


def _check_plan_letters(scene: Scene, named_at: dict[str, str]) -> None:
    """No two points the plans letter alike: each construction puts its image under its letter, the later over the
    earlier, so the plans, and the forces and error tables read off them, would come out wrong without a word.
    Points on the frame stand at the pole and have no letter of their own."""
    moving = {scene.driver.link, *(link for group in scene.groups for link in group.links)}  # type: ignore[union-attr]
    unlettered = {*scene.frame_points, *(spec.name for spec in scene.points if spec.link == scene.frame_link)}
    lettered: dict[str, str] = {}
    for name, where in named_at.items():
        if name in unlettered:
            continue
        letter = plan_letter(name)
        construction = construction_letter_clash(name, moving)
        if construction is not None:
            raise SceneError(where, f"the plans letter points in lower case, so {name} would be {letter}, the letter of "
                             f"{construction}: name it otherwise")
        other = lettered.setdefault(letter, name)
        if other != name:
            pole = " (p is the pole's letter, so P is p′)" if "p" in (name.lower(), other.lower()) else ""
            raise SceneError(where, f"the plans letter points in lower case, so {name} and the point {other} of "
                             f"{named_at[other]} would both be {letter}{pole}, one point on them: name it otherwise")


def _new_joint_where(solver: Driver | Group, name: str) -> str:
    """The key that names a joint the solver finds: ``driver.joint``, ``groups[0].joints[1]``."""
    joints = getattr(solver, "joints", None)
    if joints is None:
        return f"{solver.where}.joint"
    return f"{solver.where}.joints[{joints.index(name)}]" if name in joints else f"{solver.where}.joints"


def _check_guide(scene: Scene, guide: Guide, known_links: set[int], fixed_on: dict[int, set[str]]) -> None:
    if guide.line is not None:
        if guide.line not in scene.frame_lines:
            raise SceneError(guide.where, f"no frame line {guide.line!r}; [frame] lines has "
                             f"{_known(scene.frame_lines)}{lookalike_hint(guide.line, scene.frame_lines)}")
        return
    link = scene.frame_link if guide.link is None else guide.link
    if link not in known_links:
        raise SceneError(f"{guide.where}.link", f"link {link} is not known before this group", link)
    if not isinstance(guide.through, str) and link != scene.frame_link:
        raise SceneError(f"{guide.where}.through", f"on a moving link must name a point of link {link}", list(guide.through or ()))
    if isinstance(guide.through, str) and guide.through not in fixed_on.get(link, ()):
        if not guide.through_given:
            _refuse_implied_through(scene, guide, link, fixed_on)
        raise SceneError(f"{guide.where}.through", f"must be a point fixed on link {link}: {_known(sorted(fixed_on.get(link, ())))}",
                         guide.through, hint=lookalike_hint(guide.through, fixed_on.get(link, ())))


def _refuse_unused_frame_lines(scene: Scene, solvers: list[Driver | Group]) -> None:
    """Refuse a frame line no guide runs along: a line is read for a guide to name it, and nothing else takes it
    (no drawing shows it), so one left over is a slip, most often a guide given inline or by another name where
    the line was meant, which would then run where the scene did not mean it to."""
    guides = [guide for solver in solvers for guide in solver.guides()]
    named = {guide.line for guide in guides if guide.line is not None}
    for name in scene.frame_lines:
        _refuse_markup(name, join_path("frame.lines", name), line=True)
        if name in named:
            continue
        inline = [guide.where for guide in guides if guide.line is None and on_frame(scene, guide)]
        also = (f"; {', '.join(inline)} {'gives its line' if len(inline) == 1 else 'give their lines'} inline"
                if inline else "")
        raise SceneError(join_path("frame.lines", name), f"no guide runs along this line: name it in the guide meant "
                         f"to run on it (guide = {as_written(name, True)}), or leave it out{also}")


def _refuse_implied_through(scene: Scene, guide: Guide, link: int, fixed_on: dict[int, set[str]]) -> None:
    """Refuse a guide through a point the scene did not name for it (a triad leg's outer joint) that is not on its
    link, under the key the scene wrote, ``link``, with the link that carries the point."""
    carriers = sorted(number for number, points in fixed_on.items() if guide.through in points)
    on = "the frame" if link == scene.frame_link else f"link {link}"
    if not carriers:
        advice = ""
    elif carriers[0] == scene.frame_link:
        advice = f": leave link out, {guide.through} being a point of the frame"
    else:
        advice = f": give link = {carriers[0]}, the link that carries {guide.through}"
    raise SceneError(f"{guide.where}.link", f"the guide runs through {guide.through}, which is not on {on}{advice}",
                     *(() if guide.link is None else (guide.link,)))


def _place_points(pending, known_links, fixed_on, sliding_on, known_points):
    """Named points that can be placed now, in an order where each one's references come first."""
    placed = []
    progress = True
    while progress:
        progress = False
        for spec in list(pending):
            on_link = fixed_on.get(spec.link, set())
            toward_ok = spec.toward in on_link or spec.toward in sliding_on.get(spec.link, {})
            if spec.link in known_links and spec.start in on_link and toward_ok and spec.start != spec.toward:
                placed.append(spec)
                pending.remove(spec)
                on_link.add(spec.name)
                known_points.add(spec.name)
                progress = True
    return tuple(placed), pending


def _carriers(name: str, link: int, fixed_on, frame: int) -> str:
    """Where a point named for a link that has it not is: "; C is a point of the frame and of link 3". The slip is
    most often the link's number, or a group's joints or links given in the other order (an RPR's lever pivot
    written first), which the links that do carry it show."""
    links = sorted(other for other, names in fixed_on.items() if name in names and other != link)
    if not links:
        return ""
    parts = (["the frame"] if frame in links else []) + [f"link {other}" for other in links if other != frame]
    return f"; {name} is a point of {' and of '.join(parts)}"


def _under_pin(name: str, key: str, link: int, under_pins, sliding_on) -> str:
    """Why a link's point under a pin (an RPR lever's A4) cannot place a point: it is a different material point of
    the link at each instant, as the pin slides along it; toward the pin itself gives the slide's direction."""
    if under_pins.get(name, (None, None))[1] != link:
        return ""
    pin = under_pins[name][0]
    advice = (f": give toward = {pin!r}, the pin, whose slide gives the direction"
              if key == "toward" and pin in sliding_on.get(link, {}) else "")
    return (f"; {name} is link {link}'s point under {pin} at each instant, a different point of it as {pin} "
            f"slides{advice}")


def _unplaceable(pending: list[PointSpec], known_links, fixed_on, sliding_on, frame: int,
                 under_pins: Mapping[str, tuple[str, int]], scene: Scene) -> SceneError:
    """Why the named points left over cannot be placed: a missing reference, or else a cycle."""
    pending_names = {spec.name for spec in pending}
    for spec in pending:
        if spec.link not in known_links:
            return SceneError(f"{spec.where}.link", f"no link {spec.link} in the mechanism; links are {_known(sorted(known_links))}", spec.link)
        if spec.start == spec.toward:
            return SceneError(f"{spec.where}.toward", f"from and toward are both {spec.start!r}; they must be two points of link {spec.link}")
        on_link = fixed_on.get(spec.link, set())
        for key, name in (("from", spec.start), ("toward", spec.toward)):
            usable = name in on_link or (key == "toward" and name in sliding_on.get(spec.link, {}))
            if not usable and name not in pending_names:
                under = _under_pin(name, key, spec.link, under_pins, sliding_on)
                sliders = sorted(sliding_on.get(spec.link, {})) if key == "toward" and not under else []
                also = f" (toward may also name {', '.join(sliders)}, along the slide)" if sliders else ""
                return SceneError(f"{spec.where}.{key}", f"{name!r} is not a point of link {spec.link}; its points "
                                  f"are {_known(sorted(on_link))}{also}{lookalike_hint(name, on_link)}"
                                  f"{_carriers(name, spec.link, fixed_on, frame)}{under}"
                                  f"{_links_in_place(spec, scene)}")
    spec = pending[0]
    key, name = ("from", spec.start) if spec.start in pending_names else ("toward", spec.toward)
    if name == spec.name:
        return SceneError(f"{spec.where}.{key}", f"{name!r} is the point itself; name two other points of link {spec.link}")
    return SceneError(f"{spec.where}.{key}", f"{name!r} refers back to {spec.name!r} through the named points "
                                             f"{', '.join(sorted(pending_names))} (a cyclic reference)")


def _links_in_place(spec: PointSpec, scene: Scene) -> str:
    """Where a group's links typed in each other's places (an RRR's [4, 3]) leave the named points placed from its
    joints each on the wrong link, the links swapped back: the order that fixes every one of them on its own link.
    A point whose ``from`` or link alone was mistyped is not told so: the swap would lose another point's, or leave
    the other link with none to speak for it."""
    for solver in scene.groups:
        if spec.link not in solver.links:
            continue
        joints = set(solver.joints)
        on_its_links = [point for point in scene.points
                        if point.link in solver.links and {point.start, point.toward} <= joints]
        if spec not in on_its_links:
            return ""
        for two, in_place in _swapped(solver, "links"):
            fixed = in_place.fixed_points()
            # Both links carry a point the swap fixes: a point with one link number mistyped moves only its own.
            both = two <= {point.link for point in on_its_links}
            if both and all({point.start, point.toward} <= set(fixed.get(point.link, ())) for point in on_its_links):
                return (f"; the links typed in each other's places? {solver.where}.links = "
                        f"{as_written(list(in_place.links))} fixes {spec.start} and {spec.toward} on link {spec.link}")
    return ""


def on_frame(scene: Scene, guide: Guide) -> bool:
    return guide.link is None or guide.link == scene.frame_link


def _translating_links(scene: Scene) -> set[int]:
    """Links whose motion is a translation along a frame guide (their working sense is forward/backward)."""
    links = set()
    if scene.driver.kind == "slider":
        links.add(scene.driver.link)
    for group in scene.groups:
        if group.kind == "RRP" and on_frame(scene, group.guide):
            links.add(group.links[1])
        if group.kind == "RPP" and on_frame(scene, group.guide):
            links.update(group.links)
        if group.kind == "PRP":
            for guide, link in zip(group.guide_pair, group.links):
                if on_frame(scene, guide):
                    links.add(link)
        if group.kind == "triad":
            links.update(slider for slider, guide in group.sliders() if on_frame(scene, guide))
    return links


def _frame_guides(scene: Scene) -> dict[int, Guide]:
    """The frame guide of each link that slides along one without turning: its points move along that line alone."""
    guides = {}
    if scene.driver.kind == "slider":
        guides[scene.driver.link] = scene.driver.guide
    for group in scene.groups:
        if group.kind in ("RRP", "RPP") and on_frame(scene, group.guide):
            guides[group.links[1]] = group.guide  # an RRP's slider; an RPP's link b (its block moves with A)
        if group.kind == "PRP":
            guides.update((link, guide) for guide, link in zip(group.guide_pair, group.links) if on_frame(scene, guide))
        if group.kind == "triad":
            guides.update((slider, guide) for slider, guide in group.sliders() if on_frame(scene, guide))
    return {link: scene.frame_lines[guide.line] if guide.line is not None else guide for link, guide in guides.items()}


# A force this near square to its point's only line of motion (|cos| of the angle between them) takes from it a speed
# and a rate that the force analysis reads as rest at every position (loads' _AT_REST): no motion to resist.
_SQUARE = 1e-9


def _refuse_force_with_no_motion(mechanism: Mechanism, load) -> None:
    """Refuse a resisting force whose point never moves along its line at any position: resisting is against that
    motion, or at rest the motion about to begin, and with neither the force acted nowhere without a word."""
    scene = mechanism.scene
    if load.point in scene.frame_points:
        raise SceneError(f"{load.where}.resisting", f"{load.point} is a point of the frame (link {load.link} turns "
                         "about it), so it never moves and a force there has no motion to resist: put the force at a "
                         "point that moves, or give it a set sense (resisting = false)")
    guide = _frame_guides(scene).get(load.link)
    # A force along a point's line turns with the mechanism: square to the guide at a position or two, no more.
    if guide is None or load.along is not None or abs(math.cos(radians_within_a_turn(load.angle_deg) - guide.angle)) > _SQUARE:
        return
    raise SceneError(f"{load.where}.resisting", f"{load.point} on link {load.link} moves only along its frame guide "
                     f"(at {math.degrees(guide.angle):g}°), square to the force's line (at {load.angle_deg:g}°), so "
                     "it has no motion along that line to resist at any position: turn the force along the guide or the "
                     "guide along the force, or give it a set sense (resisting = false)")


def _as_written(window: tuple[float, float]) -> dict[str, float]:
    """A load's window of the working stroke as the scene's table writes it, for an error to show."""
    return {"from": window[0], "to": window[1]}


def _check_references(mechanism: Mechanism, known_points: set[str], known_links: set[int]) -> None:
    scene = mechanism.scene
    for number, spec in scene.links.items():
        if number not in known_links:
            raise SceneError(spec.where, f"no link {number} in the mechanism; links are {_known(sorted(known_links))}")
        if spec.centre is not None and spec.centre not in mechanism.fixed_on.get(number, ()):
            raise SceneError(f"{spec.where}.centre", f"must be a point fixed on link {number}: {_known(sorted(mechanism.fixed_on.get(number, ())))}",
                             spec.centre, hint=lookalike_hint(spec.centre, mechanism.fixed_on.get(number, ())))
    for load in scene.loads:
        if load.link not in known_links:
            raise SceneError(f"{load.where}.link", f"no link {load.link} in the mechanism", load.link)
        if load.point is not None and load.point not in mechanism.fixed_on.get(load.link, ()):
            # Named as a centre's are: "must be a point fixed on link 4" left the student to find which those are.
            raise SceneError(f"{load.where}.point", f"must be a point fixed on link {load.link}: "
                             f"{_known(sorted(mechanism.fixed_on.get(load.link, ())))}", load.point,
                             hint=lookalike_hint(load.point, mechanism.fixed_on.get(load.link, ())))
        if load.along is not None and load.along not in known_points:
            # Any named point will do, on any link: the line to it turns with whatever carries it.
            raise SceneError(f"{load.where}.along", "must be a named point of the mechanism (a frame point, a joint "
                             f"or one of [points]): {_known(sorted(known_points))}", load.along,
                             hint=(lookalike_hint(load.along, known_points)
                                   or suggestion(load.along, sorted(known_points))))
        if load.kind == "moment" and load.resisting and load.link in mechanism.translating:
            # Resisting is against the link's ω, or at rest the turning about to begin: a link that never turns has
            # neither, and the load was dropped at every position without a word.
            raise SceneError(f"{load.where}.resisting", f"link {load.link} never turns (it slides on a guide that "
                             "does not turn), so a moment resisting its turning never acts: put the moment on a link "
                             'that turns, or resist the motion with a force (kind = "force", point, angle)')
        if load.kind == "force" and load.resisting:
            _refuse_force_with_no_motion(mechanism, load)
        if load.diagram is not None and scene.positions.working is None:
            raise SceneError(f"{load.where}.diagram", "a load diagram is read over shares of the working stroke, "
                                                      "which needs positions.working (which motion of which link "
                                                      "is the working stroke)")
        if load.during != "always" and scene.positions.working is None:
            raise SceneError(f"{load.where}.during", "a load that acts in one stroke needs positions.working "
                                                     "(which motion of which link is the working stroke)",
                             _as_written(load.during) if isinstance(load.during, tuple) else load.during)
        if load.diagram is not None and not scene.driver.cyclic:
            # The diagram sets the load's window itself: refused under the window's key, it named a key never
            # written and showed a window never typed.
            run = scene.driver.run_key
            raise SceneError(f"{load.where}.diagram", "a load diagram is read over shares of the working stroke, "
                             f"which needs a crank that turns round; the positions run once over driver.{run}: "
                             'give the load a value, with during = "working" (or "idle", "always")')
        if isinstance(load.during, tuple) and not scene.driver.cyclic:
            raise SceneError(f"{load.where}.during", "a window of the working stroke needs a crank that turns "
                                                     f"round; a {scene.driver.kind} driver's positions run over its "
                                                     f"{scene.driver.run_key}, once: give the whole "
                                                     'stroke, during = "working" or "idle", or "always"',
                             _as_written(load.during))
    strokes = [scene.positions.working, *(load.stroke for load in scene.loads)]
    for working in (stroke for stroke in strokes if stroke is not None):
        if working.link not in known_links or working.link == scene.frame_link:
            raise SceneError(f"{working.where}.link", f"must be a moving link of the mechanism: {_known(mechanism.moving_links)}", working.link)
        translates = working.link in mechanism.translating
        if translates and working.sense in ("ccw", "cw"):
            raise SceneError(f"{working.where}.sense", f"link {working.link} translates: use forward or backward (along its guide)", working.sense)
        if not translates and working.sense in ("forward", "backward"):
            raise SceneError(f"{working.where}.sense", f"link {working.link} turns: use ccw or cw", working.sense)
    first = scene.positions.number_from
    last = first + scene.positions.count - 1
    for number, readings in scene.measured.items():
        if not first <= number <= last:
            raise SceneError(f"measured.{number}", f"no position {number}; positions are {first}..{last}")
        if number in scene.positions.plans:
            continue
        if number not in scene.positions.velocity_plans:
            also = f" {list(scene.positions.velocity_plans)}" if scene.positions.velocity_plans else ""
            raise SceneError(f"measured.{number}", f"position {number} is not in positions.plans "
                             f"{list(scene.positions.plans)} nor in positions.velocity_plans{also}")
        # Of a position with only a velocity plan, only that plan can be measured.
        drawn_only = [kind for kind in readings if kind != "velocity"]
        if drawn_only:
            raise SceneError(f"measured.{number}.{drawn_only[0]}", f"position {number} has only a velocity plan "
                             f"(positions.velocity_plans): add it to positions.plans to measure its {drawn_only[0]}")
