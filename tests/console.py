"""What the command line prints, as tests read it: its progress lines, which a run prints only once it has taken
more than a second, and so only on a slow or busy machine, are no part of what a test pins."""

from __future__ import annotations

import re

# cli.Progress's line of a stage: graphplan: writing the folder (1.5 s)
PROGRESS = re.compile(r"^graphplan: [a-z ,]+ \(\d+\.\d s\)$")


def without_progress(err: str) -> str:
    """``err`` without its progress lines."""
    return "".join(line for line in err.splitlines(keepends=True) if not PROGRESS.match(line.rstrip("\n")))
