"""Commented starter scenes for ``graphplan new KIND``: a working mechanism to change into one's own."""

from __future__ import annotations

from importlib import resources

# The kinds a newcomer starts from, each a scene under ``templates/``: mechanisms, and machines known without
# a linkage (a flywheel from its load diagrams, a rotor to balance on its mounts).
MECHANISMS = ("crank-rocker", "slider-crank", "slotted-lever", "shaper", "triad")
MACHINES = ("flywheel", "rotor")
KINDS = MECHANISMS + MACHINES


def starter(kind: str) -> str:
    """The commented scene of ``kind`` (one of :data:`KINDS`)."""
    if kind not in KINDS:
        raise ValueError(f"no starter scene {kind!r}; there are {', '.join(KINDS)}")
    return resources.files("graphplan").joinpath("templates", f"{kind}.toml").read_text(encoding="utf-8")
