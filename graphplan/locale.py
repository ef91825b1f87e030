"""The strings a reader sees, one TOML file per language under ``locales/``."""

from __future__ import annotations

import re
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


# The loads the analysis itself adds are named in Latin inside (results.json, errors.csv and the scene's keys keep
# those names): the inertia force Fu3 and moment Mu3, the shift hu3 of an inertia force displaced off the centre of
# mass, the balancing moment Mb or force Fb (Mb0 without friction) and the balancing force's arm hb on the lever.
# A reader sees them as the locale's textbook writes them (a Russian one: Fи3, Mи3, hи3, Mу, Fу, hу), each prefix
# spelled by the locale's own key.  A prefix counts only where the name's index follows it (a digit, the lever's
# primes for a couple's two forces, a slide's ·x) or the name ends: a load of the scene is F4 or M4.1, never these.
_LOAD_SYMBOL_KEYS = {"Fu": "symbol_inertia_force", "Mu": "symbol_inertia_moment", "hu": "symbol_inertia_shift",
                     "Mb": "symbol_balancing_moment", "Fb": "symbol_balancing_force", "hb": "symbol_balancing_arm"}
_LOAD_SYMBOL = re.compile(r"(Fu|Mu|hu|Mb|Fb|hb)(?=[\d′″·]|$)")


def load_symbol(name: str, text: Mapping[str, str]) -> str:
    """The load named ``name`` inside (Fu3, Mu3′, Mb0) as ``text``'s locale writes it (Fи3, Mи3′, Mу0 in Russian);
    any other name as it is."""
    found = _LOAD_SYMBOL.match(name)
    return text[_LOAD_SYMBOL_KEYS[found[1]]] + name[found.end():] if found else name


# Within a formula the records compose (a polygon's ΣF2 + Fb + R12 = 0), the same names as whole words.
_LOAD_SYMBOL_IN_FORMULA = re.compile(r"(?<![^\W_])(Fu|Mu|hu|Mb|Fb|hb)(?=[\d′″·]|(?![^\W_]))")


def load_symbols_in(formula: str, text: Mapping[str, str]) -> str:
    """``formula`` with every load the analysis adds named as :func:`load_symbol` names it."""
    return _LOAD_SYMBOL_IN_FORMULA.sub(lambda found: text[_LOAD_SYMBOL_KEYS[found[1]]], formula)
