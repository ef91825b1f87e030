"""The note's Markdown read a list item to a line: an item whose parts stand a line each (an equation's moments,
each line but the last ending in a backslash, Markdown's line break, and the next indented into the item) joined
into one line again, its parts set off by ``separator`` (the locale's semicolon, as a sentence would set them)."""

from __future__ import annotations


def items_on_one_line(markdown: str, separator: str = "; ") -> list[str]:
    lines: list[str] = []
    breaking = False
    for line in markdown.splitlines():
        if breaking and line.startswith("  "):
            lines[-1] += separator + line.strip().removesuffix("\\")
        else:
            lines.append(line.removesuffix("\\") if line.startswith("- ") else line)
        breaking = line.startswith(("- ", "  ")) and line.endswith("\\")
    return lines
