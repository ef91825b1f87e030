"""graphplan: the plan method of the theory of machines, from one scene file.

The Python interface::

    scene = graphplan.load("fixtures/ratchet_crank_rocker.toml")   # or graphplan.load_text(toml_text)
    shaper = graphplan.load_text(graphplan.starter("shaper", "ru"))   # `graphplan new shaper --locale ru`
    motion = graphplan.solve(scene, driver=np.radians(np.arange(0, 360, 0.01)))
    motion.point("B").r, motion.link(4).omega
"""

from __future__ import annotations

import copyreg
import importlib
import importlib.util
import warnings
from collections.abc import Sequence
from types import MappingProxyType
from typing import TYPE_CHECKING, Any

from .errors import (
    AssemblyError,
    GraphplanError,
    PositionIndexError,
    SceneError,
    SingularPositionError,
    UnknownNameError,
)

if TYPE_CHECKING:
    import numpy as np

    from .mechanism import Mechanism, build
    from .motion import Motion
    from .scene import Scene, load
    from .starters import starter

__version__ = "0.1.0"

# The interface's names from the analysis's modules, each imported when first asked for (PEP 562): the command line
# imports this package before any command, and `graphplan --help` or `graphplan new` needs none of the analysis.
_LAZY = {"Mechanism": "mechanism", "build": "mechanism", "Motion": "motion", "Scene": "scene", "load": "scene",
         "starter": "starters"}


def __getattr__(name: str) -> Any:
    if name in _LAZY:
        value = getattr(importlib.import_module(f".{_LAZY[name]}", __name__), name)
        globals()[name] = value
        return value
    # A module the package imported with itself before (`import graphplan; graphplan.scene.loads(...)`) still is.
    if not name.startswith("_") and importlib.util.find_spec(f"{__name__}.{name}") is not None:
        return importlib.import_module(f".{name}", __name__)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted({*globals(), *_LAZY})

# Scenes and motions keep their tables in read-only mappings, which pickle and deepcopy cannot take apart by
# themselves: a process pool's sweep of a parameter sends its scenes to the workers, a notebook copies one to vary.
# Registered for the process, as copyreg registers: any mapping proxy then pickles as a read-only copy of its
# mapping (graphplan's are nested deep in scenes, mechanisms and motions, where a __reduce__ apiece would not reach).
def _read_only_mapping(items: dict) -> MappingProxyType:
    return MappingProxyType(items)


copyreg.pickle(MappingProxyType, lambda proxy: (_read_only_mapping, (dict(proxy),)))


def load_text(text: str | bytes, source: str = "<scene>") -> Scene:
    """Read and check a scene given as its TOML text (or bytes), as :func:`load` reads a file; ``source`` names
    it in the errors."""
    from .scene import loads as read_text  # graphplan.loads is the module of the mechanism's loads

    return read_text(text, source)


def solve(scene: Scene, driver: Sequence[float] | np.ndarray | None = None) -> Motion:
    """The analytic motion of ``scene``'s mechanism, all positions at once.

    Parameters
    ----------
    scene
        A scene from :func:`load`.
    driver
        Driver coordinates: crank angles in rad, or slider displacements in m, in any order.
        Without it, the positions of the scene's ``[positions]`` table.  A crank's whole numbers beyond a turn
        (degrees, read as radians) warn with a ``UserWarning``; a slider's values it cannot reach are told
        against its travel.

    The velocities and accelerations are at the driver's ω and ε (a slider's velocity and acceleration) of the
    scene's ``[driver]`` table, the same at every position, as the plan method takes them.  ``Motion.warnings``
    names each position near a toggle, and each toggle between two of the positions, where the real mechanism
    may change its assembly and the positions beyond it keep the scene's.

    Returns
    -------
    Motion
        ``point(name)``'s r, v, a as ``(N, 2)`` arrays (m, m/s, m/s²), ``link(number)``'s angle, ω, ε as ``(N,)``
        arrays (rad, rad/s, rad/s², counter-clockwise positive), ``slide(slider)``'s relative motion; N is the
        number of values given (a single number is one position), all read-only.

    Raises
    ------
    SceneError
        ``driver`` no 1-D array of finite numbers (the message names the first bad value's index).
    AssemblyError
        a value the mechanism cannot reach, named by its index, with the driver's reach.
    SingularPositionError
        a value where the mechanism is at a toggle and its velocities are not determined.
    """
    import numpy as np

    from .analysis import PATH_SAMPLES
    from .mechanism import build
    from .motion import reference_at, with_toggles_between
    from .motion import solve as solve_motion
    from .positions import make_positions
    from .reach_advice import reach_hint
    from .scene import Scene, missing_part, not_a_scene

    if not isinstance(scene, Scene):
        raise not_a_scene("solve", scene)
    if not scene.has_linkage:
        raise missing_part(scene, "mechanism")
    mechanism = build(scene)
    uses_near = any(getattr(group, "near", None) is not None for group in mechanism.groups)
    # Where a crank cannot go, the error says where it can, as the command line's does.
    if driver is None:
        with reach_hint(mechanism):
            positions = make_positions(mechanism)
            return solve_motion(mechanism, positions.values, positions.reference, positions.numbers)
    try:  # where the assemblies are taken: at the first value (the solve refuses values that are no numbers)
        # Complex values are refused by the solve too: cast here, they printed numpy's warning before the refusal.
        given = None if np.iscomplexobj(driver) else np.ravel(np.asarray(driver, dtype=float))
        first: float | None = None if given is None else float(given[0])
    except (TypeError, ValueError, IndexError, OverflowError):
        given, first = None, None
    slip = _unit_slip(mechanism, given)
    try:
        with reach_hint(mechanism, first):
            reference = make_positions(mechanism).reference if uses_near else None
            motion = solve_motion(mechanism, driver, reference, indexed=True)
    except AssemblyError as error:
        if slip is None:
            raise
        raise AssemblyError(error.joint, error.position, error.group, f"{error.reason}; {slip}", error.keys) from error
    if slip is not None and mechanism.driver.kind == "crank":  # a slider's values outside its travel may be meant
        warnings.warn(f"driver: {slip}", UserWarning, stacklevel=_caller_level())
    return with_toggles_between(motion, reference or reference_at(mechanism, float(motion.driver[0])), PATH_SAMPLES)


def _caller_level() -> int:
    """The stacklevel of the first caller outside graphplan: through scene.solve() a warning named scene.py's line,
    not the notebook's cell."""
    import sys
    from pathlib import Path

    package = str(Path(__file__).parent)
    frame, level = sys._getframe(1), 1  # solve's frame: stacklevel 1
    while frame is not None and frame.f_code.co_filename.startswith(package):
        frame, level = frame.f_back, level + 1
    return level


def _unit_slip(mechanism: Mechanism, values: np.ndarray | None) -> str | None:
    """What to say of driver values that look given in the wrong unit, or None: a crank's whole numbers beyond a turn
    (degrees, read as radians: np.arange(0, 360, 30) is 52 turns), a slider's values outside its travel (metres,
    a thousand times it where they are millimetres).  Only said, never changed: 7 rad may be meant."""
    import numpy as np

    if values is None or not values.size or not np.all(np.isfinite(values)):
        return None
    driver = mechanism.driver
    largest = float(np.max(np.abs(values)))
    if driver.kind == "crank":
        if largest <= 2 * np.pi or not np.all(values == np.round(values)):
            return None
        return (f"the values are whole numbers up to {largest:g}, read as radians ({largest:g} rad is "
                f"{largest / (2 * np.pi):.3g} turns): for degrees give np.radians(values)")
    low, high = sorted(driver.travel)
    margin = 1e-9 * (high - low)  # np.linspace's last value a hair past the end is within the travel
    if np.all((values >= low - margin) & (values <= high + margin)):
        return None
    said = f"the scene's travel is s = {driver.travel[0]:g} … {driver.travel[1]:g} m and the values are in metres"
    thousandth = values / 1000.0
    if largest > 10 * max(abs(low), abs(high)) and np.all((thousandth >= low - margin) & (thousandth <= high + margin)):
        said += ": given in millimetres? divide them by 1000"
    return said


__all__ = [
    "AssemblyError",
    "GraphplanError",
    "Mechanism",
    "Motion",
    "PositionIndexError",
    "Scene",
    "SceneError",
    "SingularPositionError",
    "UnknownNameError",
    "__version__",
    "build",
    "load",
    "load_text",
    "solve",
    "starter",
]
