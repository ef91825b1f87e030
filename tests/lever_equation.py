"""Zhukovsky's lever's ΣMp read back a term for each load, for the tests that check its terms against the lever.

The caption takes an arm that several loads share out of brackets (``− (Mu3′ − Mf23′ + Mf43′)·h3``); a reader who
checks each load's moment multiplies it back in: ``− Mu3′·h3 + Mf23′·h3 − Mf43′·h3``.
"""

from __future__ import annotations

import re

# A bracketed sum times one arm, with the sign in front of the bracket (none where it leads the equation).
FACTORED = re.compile(r"(?:([+−]) ?)?\(([^()]*)\)·(h\w+)")
SIGNED_NAME = re.compile(r"([+−]?)\s*([^\s+−]+)")


def unfactored(equation: str) -> str:
    """``equation`` with each bracketed term multiplied out, every sign set apart from its name: ``+ A·h3``."""
    def multiplied(match: re.Match[str]) -> str:
        outer, inside, arm = match.groups()
        return " ".join(f"{'−' if (sign == '−') != (outer == '−') else '+'} {name}·{arm}"
                        for sign, name in SIGNED_NAME.findall(inside))

    return FACTORED.sub(multiplied, equation)
