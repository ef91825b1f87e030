"""bench/label_clutter.py as the tests load it: the bench's own count of labels on lines, which the tests of labels
kept off lines hold the drawings to."""

from __future__ import annotations

import functools
import importlib.util
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


@functools.cache
def label_clutter():
    """The bench's module, loaded once as the bench runs it (its recorder patches the placer while it counts)."""
    spec = importlib.util.spec_from_file_location("label_clutter", ROOT / "bench" / "label_clutter.py")
    module = importlib.util.module_from_spec(spec)
    sys.modules.setdefault(spec.name, module)
    spec.loader.exec_module(module)
    return module
