"""The strings a reader sees, one TOML file per language under ``locales/``."""

from __future__ import annotations

import tomllib
from collections.abc import Mapping
from functools import cache
from importlib import resources


@cache
def strings(locale: str) -> Mapping[str, str]:
    """All strings of ``locale``; a key missing there falls back to English."""
    english = _read("en")
    if locale == "en":
        return english
    return {**english, **_read(locale)}


# Remembered apart from strings(): every other locale's strings fall back on English's, which a run in Russian
# asks for as well (the diagrams' words), and the file took a parse of its own each time.
@cache
def _read(locale: str) -> dict[str, str]:
    text = resources.files("graphplan").joinpath("locales", f"{locale}.toml").read_text(encoding="utf-8")
    return tomllib.loads(text)


class Count(int):
    """A count that a locale's string follows by its noun in the form the number takes: ``{count:форма|формы|форм}``
    writes that noun (``{count}`` the number itself).

    The forms given choose the rule: three, Russian's (1, 21, 101 take the first; 2–4, 22–24 the second; 0, 5–20,
    25–30, and 11–14 after any hundred, the third), two, English's (1 the first, any other count the second).  A
    language whose nouns do not change with their number (Chinese) writes its noun outside the braces.
    """

    def __format__(self, spec: str) -> str:
        if "|" not in spec:
            return super().__format__(spec)
        forms = spec.split("|")
        if len(forms) == 2:
            return forms[0] if self == 1 else forms[1]
        if len(forms) != 3:
            raise ValueError(f"a count's noun takes two or three forms, not {len(forms)}: {spec!r}")
        last, last_two = abs(self) % 10, abs(self) % 100
        if last == 1 and last_two != 11:
            return forms[0]
        if 2 <= last <= 4 and not 12 <= last_two <= 14:
            return forms[1]
        return forms[2]
