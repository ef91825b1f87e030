"""One run's analysis: everything the outputs read, computed once.

The command line and the Python interface both go through :func:`analyse`,
so that the numbers in ``results.json``, the drawings and a notebook agree.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .mechanism import Mechanism, build
from .motion import Motion, solve
from .positions import PositionSet, make_positions
from .scene import Scene

# Driver positions per cycle for the paths drawn on the plan of positions.
PATH_SAMPLES = 360


@dataclass(frozen=True)
class Analysis:
    scene: Scene
    mechanism: Mechanism
    positions: PositionSet
    motion: Motion
    emphasised: Motion
    paths: Motion


def analyse(scene: Scene) -> Analysis:
    """Build the mechanism, place the positions and solve them, with the extremes and a dense sweep."""
    mechanism = build(scene)
    positions = make_positions(mechanism)
    motion = solve(mechanism, positions.values, positions.reference, positions.numbers)
    # The positions drawn bold: the working link's two extremes, a slider driver's two ends, or the first position.
    if positions.extremes is not None:
        bold = np.array(positions.extremes)
    elif mechanism.driver.kind == "slider":
        bold = positions.values[[0, -1]]
    else:
        bold = positions.values[:1]
    emphasised = solve(mechanism, bold, positions.reference)
    driver = mechanism.driver
    if driver.kind == "crank":
        sweep = positions.values[0] + driver.sense * np.linspace(0.0, 2.0 * np.pi, PATH_SAMPLES + 1)
    else:
        sweep = np.linspace(driver.travel[0], driver.travel[1], PATH_SAMPLES + 1)
    paths = solve(mechanism, sweep, positions.reference)
    return Analysis(scene, mechanism, positions, motion, emphasised, paths)
