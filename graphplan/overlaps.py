"""Parts of a mechanism that stand on one another: a group given twice, two blocks that run through each other.

A second cylinder of a twin given the first one's guide and rod (its angle left out) solves without a fault: its
joints stand on the first's at every position, and every plan, load and sheet draws the two over one another
without a word.  Two blocks on one fixed guide whose order along it changes over the cycle pass through each
other, which no machine does.  Both are told once, as warnings about the scene as a whole.
"""

from __future__ import annotations

import itertools

import numpy as np

from .mechanism import Mechanism
from .motion import Motion, PositionWarning

# Two paths closer than this share of the mechanism's size at every position are one path: the groups solve to
# round-off (1e-12 of the size), and no linkage a student draws has two joints 1 µm apart on a 1 m frame.
SAME_PLACE = 1e-6


def overlaps(mechanism: Mechanism, paths: Motion) -> tuple[PositionWarning, ...]:
    """The warnings of parts that stand on one another over ``paths`` (the plan of positions' sweep): joints that
    coincide throughout, then blocks that pass through each other, each measured against the mechanism's size."""
    size = _size(paths)
    return _coinciding_joints(mechanism, paths, size) + _blocks_passing_through(mechanism, paths, size)


def _coinciding_joints(mechanism: Mechanism, paths: Motion, size: float) -> tuple[PositionWarning, ...]:
    """A ``joints-coincide`` warning for each two joints the groups find that stand at one place at every position of
    ``paths``, naming the groups that found them."""
    found = {joint: group for group in mechanism.groups for joint in group.new_joints()}
    told = []
    for (first, first_group), (second, second_group) in itertools.combinations(found.items(), 2):
        gap = np.hypot(*(paths.point(first).r - paths.point(second).r).T)
        if not np.isfinite(gap).any() or not np.nanmax(gap) <= SAME_PLACE * size:
            continue
        same = "group" if first_group is second_group else "groups"
        whose = first_group.label if first_group is second_group else f"{first_group.label} and {second_group.label}"
        told.append(PositionWarning(0, "joints-coincide", (
            f"joints {first} and {second} ({same} {whose}) stand at one place at every position: their links are "
            f"drawn on one another in every plan and sheet; is a group given twice, or a second guide's angle or a "
            f"second rod's length left as the first one's?")))
    return tuple(told)


def _blocks_passing_through(mechanism: Mechanism, paths: Motion, size: float) -> tuple[PositionWarning, ...]:
    """A ``blocks-pass-through`` warning for each two blocks sliding on one line of the frame whose order along it
    changes over the sweep ``paths``: they run through each other where their places along the line cross."""
    frame = mechanism.scene.frame_link
    slides = [slide for slide in paths.slides if slide.guide == frame]
    told = []
    for first, second in itertools.combinations(slides, 2):
        along = np.asarray(first.u, dtype=complex) * np.ones(paths.count)
        a, b = (_complex(paths.point(slide.joint).r) for slide in (first, second))
        # One line: the same direction, and the second block on the first's line at every position.
        if not (np.nanmax(np.abs(np.imag(np.asarray(second.u) * np.conj(along)))) <= SAME_PLACE and
                np.nanmax(np.abs(np.imag((b - a) * np.conj(along)))) <= SAME_PLACE * size):
            continue
        ahead = np.real((b - a) * np.conj(along))
        if np.nanmax(np.abs(ahead)) <= SAME_PLACE * size:
            continue  # one place throughout: told as joints that coincide
        if not (np.nanmin(ahead) < 0.0 < np.nanmax(ahead)):
            continue
        sense = np.sign(ahead)
        # Where the sweep has no position (a swing's), there is no crossing to tell: from one sample to the next.
        changes = np.flatnonzero(np.isfinite(ahead[:-1]) & np.isfinite(ahead[1:]) & (sense[:-1] != sense[1:]))
        crossing = int(changes[0]) + 1 if changes.size else int(np.nanargmin(np.abs(ahead)))
        told.append(PositionWarning(0, "blocks-pass-through", (
            f"the blocks at {first.joint} (link {first.slider}) and {second.joint} (link {second.slider}) slide on one "
            f"line of the frame and pass through each other ({mechanism.driver.describe(float(paths.driver[crossing]))}"
            f"): their order along the line changes over the cycle, which no machine's blocks do; give each its own "
            f"line (a twin's second cylinder at its own angle)")))
    return tuple(told)


def _size(paths: Motion) -> float:
    """The largest extent of the paths of ``paths``' points: the mechanism's size."""
    every = np.concatenate([paths.point(name).r for name in paths.points])
    return float(np.nanmax(np.nanmax(every, axis=0) - np.nanmin(every, axis=0))) or 1.0


def _complex(r: np.ndarray) -> np.ndarray:
    return r[:, 0] + 1j * r[:, 1]
