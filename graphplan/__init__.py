"""graphplan: the plan method of the theory of machines, from one scene file.

The Python interface::

    scene = graphplan.load("fixtures/ratchet_crank_rocker.toml")
    motion = graphplan.solve(scene, driver=np.radians(np.arange(0, 360, 0.01)))
    motion.point("B").r, motion.link(4).omega
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from .errors import AssemblyError, GraphplanError, SceneError, SingularPositionError
from .mechanism import Mechanism, build
from .motion import Motion
from .scene import Scene, load

__version__ = "0.1.0"


def solve(scene: Scene, driver: Sequence[float] | np.ndarray | None = None) -> Motion:
    """The analytic motion of ``scene``'s mechanism, all positions at once.

    Parameters
    ----------
    scene
        A scene from :func:`load`.
    driver
        Driver coordinates: crank angles in rad, or slider displacements in m.
        Without it, the positions of the scene's ``[positions]`` table.
    """
    from .motion import solve as solve_motion
    from .positions import make_positions

    mechanism = build(scene)
    uses_near = any(getattr(group, "near", None) is not None for group in mechanism.groups)
    if driver is None or uses_near:
        positions = make_positions(mechanism)
        if driver is None:
            return solve_motion(mechanism, positions.values, positions.reference, positions.numbers)
        return solve_motion(mechanism, driver, positions.reference)
    return solve_motion(mechanism, driver)


__all__ = [
    "AssemblyError",
    "GraphplanError",
    "Mechanism",
    "Motion",
    "Scene",
    "SceneError",
    "SingularPositionError",
    "__version__",
    "build",
    "load",
    "solve",
]
