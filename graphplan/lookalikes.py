"""Names that look the same on screen but are other characters: a Cyrillic С typed for the Latin C, a hyphen
for the en dash a starter names its guide with, a full-width Ａ from a Chinese input method.

A scene's names are looked up among the names it has given already; where the two differ only in such
characters, an error that shows both ("must be one of O, C (got 'О')") contradicts itself on screen, and one
that letters two points alike (a Cyrillic С beside the Latin C) draws sheets with two points C.  This module
tells such names apart and says which character is which, for every place that looks a name up.

The plans letter points in lower case (B → b), so two names that differ in case alone (b beside B, s3 beside S3),
or one whose letter is a construction's own (N3 beside the normal component's n3), would be one point on them:
:func:`plan_letter` and :func:`construction_letter_clash` tell the reader which.
"""

from __future__ import annotations

import difflib
import re
import unicodedata
from collections.abc import Iterable, Mapping
from typing import Any

# Letters drawn like a Latin one: what a Russian keyboard types for the Latin names beside them (and Greek capitals,
# which a mathematical font draws the same).  Every dash and the minus sign read as the hyphen a keyboard has.
_LOOKS_LATIN = str.maketrans({
    **dict(zip("АВСЕНКМОРТХУЅІЈаесорхуѕіј", "ABCEHKMOPTXYSIJaecopxysij")),
    **dict(zip("ΑΒΕΖΗΙΚΜΝΟΡΤΥΧο", "ABEZHIKMNOPTYXo")),
    **dict.fromkeys("‐‑‒–—―−", "-"),
})


def plain(name: str) -> str:
    """``name`` as it looks: every character that looks like an ASCII one replaced by it (full-width forms too)."""
    return unicodedata.normalize("NFKC", name).translate(_LOOKS_LATIN)


def twin(name: str, names: Iterable[str]) -> str | None:
    """The one of ``names`` that is not ``name`` but looks the same, or None."""
    looks = plain(name)
    return next((other for other in names if other != name and plain(other) == looks), None)


def described(character: str) -> str:
    """A character as an error names it, so that two that look the same read apart: "the Cyrillic 'С' (U+0421)",
    "a hyphen '-' (U+002D)", "an en dash '–' (U+2013)"."""
    name = unicodedata.name(character, "")
    code = f"'{character}' (U+{ord(character):04X})"
    for script in ("LATIN", "CYRILLIC", "GREEK"):
        if name.startswith(script):
            return f"the {script.capitalize()} {code}"
    if name.startswith("FULLWIDTH"):
        return f"the full-width {code}"
    what = {"HYPHEN-MINUS": "a hyphen"}.get(name) or f"a{'n' if name[:1] in 'AEIOU' else ''} {name.lower()}"
    return f"{what} {code}"


def full_width(character: str) -> bool:
    """Whether ``character`` is a wide form (a Chinese or Japanese input method's Ａ, ＝, ０), not a letter that
    folds to ASCII for another reason (a subscript ₁ or superscript ¹ typed on purpose)."""
    return unicodedata.decomposition(character).startswith("<wide>")


def difference(typed: str, meant: str) -> str:
    """What sets ``typed`` apart from ``meant``, which looks the same, and what to type: "'О' has the Cyrillic 'О'
    (U+041E) where 'O' has the Latin 'O' (U+004F): type the Latin letter"."""
    wide = all(full_width(mine) for mine in typed if not mine.isascii())
    if wide and unicodedata.normalize("NFKC", typed) == meant:  # a Chinese input method's full-width forms
        return f"it has full-width letters: write {meant}"
    return f"{contrast(typed, meant)}: {_advice(typed, meant)}"


def contrast(typed: str, meant: str) -> str:
    """Each character of ``typed`` beside the one of ``meant`` it looks like: "'О' has the Cyrillic 'О' (U+041E)
    where 'O' has the Latin 'O' (U+004F)"."""
    if len(typed) == len(meant):
        pairs = [(mine, theirs) for mine, theirs in zip(typed, meant) if mine != theirs]
    else:  # a full-width form folds to more than one character: name the typed ones alone
        pairs = [(mine, "") for mine in dict.fromkeys(typed) if not mine.isascii()]
    pairs = list(dict.fromkeys(pairs))
    mine = ", ".join(described(a) for a, _ in pairs)
    theirs = ", ".join(described(b) for _, b in pairs if b)
    return f"{typed!r} has {mine}" + (f" where {meant!r} has {theirs}" if theirs else "")


def _advice(typed: str, meant: str) -> str:
    pairs = [(mine, theirs) for mine, theirs in zip(typed, meant) if mine != theirs] if len(typed) == len(meant) \
        else []
    if pairs and all(theirs.isascii() for _, theirs in pairs):
        if all(theirs.isalpha() for _, theirs in pairs):
            return "type the Latin letter" + ("s" if len(set(pairs)) > 1 else "")
        return f"type {meant!r}"
    if not pairs and meant.isascii():
        return f"type {meant!r}"
    return f"write it as {meant!r} is written (copy it), or name both alike in ASCII"


def plan_letter(point: str) -> str:
    """The letter the plans give the image of ``point``: ``B`` → ``b``, ``S3`` → ``s3``.

    ``p`` is the pole's, so a point named P is lettered ``p′``.
    """
    letter = point.lower()
    return f"{letter}′" if letter == "p" else letter


# The letters the constructions give their own points: the ends of normal components (n3, the triad's n5′, n5″)
# and the triad's special point Σ5 (σ5), each followed by a link's number.
_CONSTRUCTION_LETTER = re.compile(r"([nσ])(\d+)[′″]*")


def construction_letter_clash(point: str, moving_links: Iterable[int]) -> str | None:
    """What the constructions letter as ``point``'s plan letter, where a construction of one of ``moving_links`` does
    ("the end of a normal component (aⁿ) on link 3"), else None."""
    match = _CONSTRUCTION_LETTER.fullmatch(plan_letter(point))
    if match is None or int(match.group(2)) not in set(moving_links):
        return None
    if match.group(1) == "σ":
        return f"the special point of the triad whose ternary link is {match.group(2)}"
    return f"the end of a normal component (aⁿ) on link {match.group(2)}"


def lookalike_hint(name: str, names: Iterable[str]) -> str:
    """The hint for a ``name`` looked up among ``names`` and not found, where one of them looks the same:
    "; 'О' has the Cyrillic 'О' … where 'O' has the Latin 'O' …: type the Latin letter"; else ""."""
    meant = twin(name, names)
    return f"; {difference(name, meant)}" if meant is not None else ""


class NamedValues(dict):
    """Values by name, where a name they have not is told with the names they have and the nearest, as the scene's
    keys are: ``values["omega_4"]`` and ``reactions["R32"]`` gave a bare KeyError. ``told`` says what the values
    are, as "is no value of the plans, which give"."""

    def __init__(self, values: Mapping[str, Any], told: str) -> None:
        super().__init__(values)
        self.told = told

    def __missing__(self, key: object) -> Any:
        hint = lookalike_hint(key, self) if isinstance(key, str) else ""
        if not hint:
            hint = self._nearest(str(key))
        raise KeyError(f"{key!r} {self.told} {', '.join(self) or 'none'}{hint}")

    def _nearest(self, key: str) -> str:
        """"; did you mean …?" with the name ``key`` likely meant, or "": a reaction named the other way round
        (R32 for R23, which difflib took for R34), a name as the tables print it (ω4 for omega4) or in another
        case (vb for VB), else the nearest in spelling."""
        pair = re.fullmatch(r"[Rr](\d)(\d)", key)
        if pair and (turned := f"R{pair[2]}{pair[1]}") in self:
            return f"; did you mean {turned!r} (R{pair[1]}{pair[2]} = −{turned})?"
        spelled = key.replace("ω", "omega").replace("ε", "epsilon")
        same = [name for name in self if name.casefold() == spelled.casefold()]
        near = same or difflib.get_close_matches(spelled, list(self), n=1)
        return f"; did you mean {near[0]!r}?" if near else ""

    def __reduce__(self):  # copied or pickled with what it says of a missing name
        return (type(self), (dict(self), self.told))


__all__ = ["NamedValues", "construction_letter_clash", "contrast", "described", "difference", "lookalike_hint", "plain",
           "plan_letter", "twin"]
