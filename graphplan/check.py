"""Readings off the plans and the table of their errors against the analytic solution.

A reading is a length of the drawing, in mm, between two plan points (``pb``,
``ab``, ``n3b``), turned into a quantity by the scale and, for ω and ε, by a
link's length: ``VB = pb·μV``, ``ω3 = ab·μV / lAB``, ``ε3 = n3b·μa / lAB``.
Three sources give the lengths: the plan as constructed, the same plan read
with a ruler to the drafting precision, and the readings a student took off a
hand-drawn plan (the scene's ``[measured]``).  Each quantity is compared with
the exact value: ``δ = (analytic − plan) / analytic · 100 %``.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from typing import Mapping

from .errors import SceneError
from .mechanism import Mechanism
from .plans import Plan

SOURCES = ("construction", "drafting", "measured")


@dataclass(frozen=True)
class Reading:
    """How one quantity is read off a plan.

    ``segment`` is the pair of plan letters whose distance is measured;
    ``length`` the link length it is divided by (1 for a linear quantity);
    ``sign`` the sense the construction gives it (+1 ccw, −1 cw) for ω and ε,
    and 1 for magnitudes; ``points`` the two mechanism points (B, A) of a
    relative vector vBA.
    """

    quantity: str
    plan: str
    segment: tuple[str, str]
    length: float = 1.0
    sign: float = 1.0
    points: tuple[str, str] | None = None

    def value(self, plans: Mapping[str, Plan], millimetres: float | None = None) -> float:
        """The quantity from the segment's length (``millimetres`` overrides the plan's own)."""
        plan = plans[self.plan]
        mm = abs(plan.mm(self.segment[1]) - plan.mm(self.segment[0])) if millimetres is None else millimetres
        return self.sign * mm * plan.scale / self.length

    def millimetres(self, plans: Mapping[str, Plan]) -> float:
        plan = plans[self.plan]
        return abs(plan.mm(self.segment[1]) - plan.mm(self.segment[0]))


@dataclass(frozen=True)
class ErrorRow:
    position: int
    quantity: str
    analytic: float
    plan: float
    source: str

    @property
    def percent(self) -> float:
        """(analytic − plan) / analytic · 100; 0 when both are zero."""
        if self.analytic == 0:
            return 0.0 if self.plan == 0 else math.inf
        return (self.analytic - self.plan) / self.analytic * 100.0


def readings(mechanism: Mechanism, plans: Mapping[str, Plan], positions: Mapping[str, complex]) -> list[Reading]:
    """Every quantity the plans give, in textbook order: absolute, relative, then angular."""
    result: list[Reading] = []
    frame = set(mechanism.scene.frame_points)
    for kind, symbol in (("velocity", "V"), ("acceleration", "a")):
        plan = plans[kind]
        moving = [name for name in plan.images if name not in frame and name in positions]
        result += [Reading(f"{symbol}{name}", kind, ("p", plan.images[name])) for name in moving]
        for name, first, second in _relative_pairs(mechanism, plans["velocity"]):
            result.append(Reading(f"{symbol}{name}", kind, (plan.images[first], plan.images[second]),
                                  points=(second, first)))
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
    named = [name for name in plan.images if name in positions and (positions[name], plan.images[name]) in members]
    for step in plan.steps:
        for vector in step.vectors:
            if not vector.meaning.endswith("^τ"):
                continue
            pair = _point_pair(vector.meaning[1:-2], named)
            if pair is not None and positions[pair[0]] != positions[pair[1]]:
                return Reading(f"epsilon{link}", kind, (vector.start, vector.end),
                               abs(positions[pair[0]] - positions[pair[1]]), sign)
    return None


def _point_pair(text: str, names: list[str]) -> tuple[str, str] | None:
    """``"BA"`` → ``("B", "A")`` when both are among ``names`` (longest names tried first)."""
    for first in sorted(names, key=len, reverse=True):
        if text.startswith(first) and text[len(first):] in names:
            return first, text[len(first):]
    return None


def drafted(millimetres: float, precision: float) -> float:
    """A length as a person reads it with a ruler: rounded to the drafting precision."""
    return round(millimetres / precision) * precision


def error_rows(position: int, analytic: Mapping[str, float], plans: Mapping[str, Plan], table: list[Reading],
               precision: float, measured: Mapping[str, Mapping[str, float]] | None = None) -> list[ErrorRow]:
    """The error table of one position: every reading against the analytic value, per source."""
    rows = []
    for reading in table:
        exact = analytic[reading.quantity]
        rows.append(ErrorRow(position, reading.quantity, exact, reading.value(plans), "construction"))
        rows.append(ErrorRow(position, reading.quantity, exact,
                             reading.value(plans, drafted(reading.millimetres(plans), precision)), "drafting"))
    if measured:
        rows += _measured_rows(position, analytic, plans, table, measured)
    return rows


def _measured_rows(position, analytic, plans, table, measured) -> list[ErrorRow]:
    """Rows for the scene's hand readings: each segment gives every quantity read from that segment."""
    rows = []
    for kind, lengths in measured.items():
        letters = sorted(plans[kind].points, key=len, reverse=True)
        for segment_name, millimetres in lengths.items():
            segment = split_segment(segment_name, letters, f"measured.{position}.{kind}.{segment_name}")
            matches = [r for r in table if r.plan == kind and set(r.segment) == set(segment)]
            if not matches:
                raise SceneError(f"measured.{position}.{kind}.{segment_name}",
                                 f"the plan has no quantity read from {segment[0]}{segment[1]}")
            for reading in matches:
                rows.append(ErrorRow(position, reading.quantity, analytic[reading.quantity],
                                     reading.value(plans, millimetres), "measured"))
    return rows


def split_segment(name: str, letters: list[str], where: str) -> tuple[str, str]:
    """``"n3b"`` → ``("n3", "b")``: the two plan letters a segment's name joins."""
    for first in letters:
        if name.startswith(first) and name[len(first):] in letters:
            return (first, name[len(first):])
    raise SceneError(where, f"is not two letters of the plan ({', '.join(sorted(letters))})")


_QUANTITY = re.compile(r"^(V|a|omega|epsilon)(.*)$")


def analytic_values(mechanism: Mechanism, table: list[Reading], velocities: Mapping[str, complex],
                    accelerations: Mapping[str, complex], omega: Mapping[int, float],
                    epsilon: Mapping[int, float]) -> dict[str, float]:
    """The exact value of every quantity of ``table``: magnitudes, and signed ω, ε."""
    values: dict[str, float] = {}
    for reading in table:
        kind, rest = _QUANTITY.match(reading.quantity).groups()  # type: ignore[union-attr]
        if kind == "omega":
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

