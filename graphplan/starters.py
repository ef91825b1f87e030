"""Commented starter scenes for ``graphplan new KIND``: a working mechanism to change into one's own."""

from __future__ import annotations

import re
from importlib import resources

from .scene import LOCALES

# The kinds a newcomer starts from, each a scene under ``templates/``: mechanisms, and machines known without
# a linkage (a flywheel from its load diagrams, a rotor to balance on its mounts).
MECHANISMS = ("crank-rocker", "slider-crank", "slotted-lever", "shaper", "triad")
MACHINES = ("flywheel", "rotor")
KINDS = MECHANISMS + MACHINES


def starter(kind: str, locale: str = "en") -> str:
    """The commented scene of ``kind`` (one of :data:`KINDS`), its drawings and note in ``locale`` (its comments
    stay English)."""
    if kind not in KINDS:
        raise ValueError(f"no starter scene {kind!r}; there are {', '.join(KINDS)}")
    if locale not in LOCALES:
        raise ValueError(f"no locale {locale!r}; there are {', '.join(LOCALES)}")
    text = resources.files("graphplan").joinpath("templates", f"{kind}.toml").read_text(encoding="utf-8")
    return re.sub(r'^(locale\s*=\s*)"en"', rf'\1"{locale}"', text, count=1, flags=re.MULTILINE)
