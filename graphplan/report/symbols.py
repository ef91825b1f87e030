"""The textbook's symbols in the note's running text, with their indices told apart.

The note writes its symbols flat, as plain text allows: ``VBA``, ``aBAτ`` (the plans' ``aBA^τ``), ``aBB4ʳ``,
``ω3``, ``μV``, ``R23τ``, ``JF``, ``ΔWmax``, and with a Russian textbook's indices ``Jм``, ``ωср``,
``ΔTнб``; Assur's special point is an index like a letter (``VDΣ6``); a point is numbered by its link (``A4``, ``Σ6``),
and a plan's vectors run their points together (``ps2``, ``πn3``: p to s₂, π to n₃), as the drawings letter them.  :func:`pieces` splits a text into plain runs and
:class:`Symbol` parts (base, index, component), so that the HTML
(:mod:`graphplan.report.html`) and the LaTeX (:mod:`graphplan.report.latex`)
each set the indices as sub- and superscripts in their own markup.  Only a
closed list of shapes is recognised (:data:`SYMBOL`), none of which is a word
of the note's languages.
"""

from __future__ import annotations

import functools
import re
from collections.abc import Collection, Iterator
from typing import NamedTuple

#: The capitals a point's name is written in, as the body of a regular expression's class: Latin, Cyrillic (a
#: Russian scheme's О, А, В) and Greek (Assur's Σ6) alike, since a scene may name its points in any of them.
CAPITALS = "A-ZА-ЯЁΑ-Ω"
# A point's name, or two of them, as an index: a capital, then capitals and digits (B4, S3, ВА, Σ6C).
_POINTS = f"[{CAPITALS}][{CAPITALS}0-9]*"

# A rotor's mass or correction plane as an index: numbered (1, 12), lettered as the scenes letter them (A, Ab, L), the
# static correction's b, or the textbook's running i.
_ROTOR = f"\\d{{1,3}}|[{CAPITALS}][A-Za-z0-9]{{0,2}}|[bi]"

# Every character a symbol below begins with: asked first, so that the shapes are tried only where one may begin (the
# note's and the tables' texts were scanned nine times slower, every shape tried at every character).  A shape added
# with another first character adds it here (tests/test_run_speed_paths.py holds the symbols found to the shapes').
FIRST_CHARACTERS = "VaslωεψμRFMGJmIpnPφXfρΔAWv(zrh"

# base, index, component: the symbols of the plan method and of the force analysis.
SYMBOL = re.compile(
    rf"(?=[{re.escape(FIRST_CHARACTERS)}])"
    # A derivative's d stands before the speed it differentiates: dωd/dt is d of ωd.
    r"(?:(?<![A-Za-z_])|(?<=(?<![A-Za-z_])d)(?=ω))(?:"
    # A point's travel along its guide (sE, the load diagrams' abscissa) is indexed as its velocity is.
    rf"(?P<base>[Vas]|l)(?P<index>{_POINTS})(?P<component>ⁿ|ᵏ|ʳ|\^?τ|\^r)?"
    r"|(?P<base12>a)(?P<component12>\^?τ)"
    # A rocker's angle (ψ4) is indexed by its link as its ω and ε are.
    r"|(?P<base2>[ωεψ])(?P<index2>\d+)"
    # A scale: of velocities, accelerations, forces and lengths, and the diagrams' (μs, μv, μt, μφ, μψ, μω, με, μM, μT,
    # μJ, μA; in Chinese the works' and the energy's μW, μE), and the reduced mass's μm where it is given, not the
    # micrometre.
    r"|(?P<base3>μ)(?P<index3>[VaFlvstφψωεMTJAWE]|m(?= = ))"
    r"|(?P<base4>R)(?P<index4>\d+)(?P<component4>τ|n)?"
    # A Russian textbook's inertia loads and balancing load (Fи3, Mи3, Mу, Mу0, Fу), the locale's spelling of Fu3, Mb.
    r"|(?P<base5>[FM])(?P<index5>u\d*|b\d*|f\d+|\d+|[edr]|[иу]\d*|[пдст])"
    r"|(?P<base6>F)(?P<index6>y)"
    r"|(?P<base7>[GJ])(?P<index7>\d+|S|e,mean|e,m|[Fe]′?|п,ср|пI|[пм]′?)|(?P<base11>m)(?P<index11>\d+|e|п)"
    # The arm of the balancing force on Zhukovsky's lever (hb, in Russian hу) and the shift of an inertia force from
    # its centre of mass (hu4, hи4), as the drawings letter them.
    r"|(?P<base34>h)(?P<index34>[bу]|[uи]\d+)"
    # ΣMp: Zhukovsky's lever's moments about its pole p.
    rf"|(?<=Σ)(?P<base8>M)(?P<index8>{_POINTS}|p)"
    # A group's class with its order in the structure formula (II2(3,4)), which the textbooks set as II₂.
    r"|(?P<base27>III|II|I)(?P<index27>\d)(?=\()"
    r"|(?P<base9>p)(?P<index9>[45])"
    # (The crank's speed in rev/min, n2 in πn2/30, is indexed as the plans' n3 is: :data:`NUMBERED_POINTS`.)
    # A motor's synchronous and rated speeds in rev/min in the initial data (ns, nN, nн), given as values: only so,
    # where ns may be a plan's vector from n to s.
    r"|(?P<base33>n)(?P<index33>[sNн])(?= = )"
    r"|(?P<base10>P)(?P<index10>[LH])"
    # The strokes' angles of the crank (φw, φi; φр.х, φх.х), the reactions of the linear system and of the
    # polygons (Rсист, Rпл), an error's two values (Xа, Xпл); the friction in a pair: its coefficient fE (reduced
    # in a V-guide, f′E), its circle's radius ρO, its force Ff16 and moment Mf12 (above).
    r"|(?P<base18>φ)(?P<index18>[wi]|р\.х|х\.х)|(?P<base19>R)(?P<index19>сист|пл)|(?P<base20>X)(?P<index20>а|пл)"
    rf"|(?P<base21>f′?|ρ)(?P<index21>{_POINTS}|\d+)"
    # A journal's radius in a pair (rO) beside its f and ρ in the initial data.
    rf"|(?P<base32>r)(?P<index32>{_POINTS})"
    # The machine's dynamics: ΔWmax, Ad and Ar (in Chinese Wd and Wr), ωm, ωmax and ωmin, vS of a reduction; in
    # Russian ΔTнб, Aд and Aс, ωср (and above Je,mean, Jп, Jп,ср, Mп, Mд, Mс, mп).  The efficiency over the cycle's
    # works: Au, Ab (the driver's, with friction), Af (Wr, Wb, Wf; Aпс, Aдв, Aтр).
    r"|(?P<base13>ΔW)(?P<index13>max)|(?P<base17>ΔT)(?P<index17>нб)|(?P<base14>[AW])(?P<index14>[bdfru]|[дс]|пс|дв|тр)"
    r"|(?P<base15>ω)(?P<index15>max|min|m|ср)|(?P<base16>v)(?P<index16>S)"
    # The motor: its rated (MN, ωN, sN; Mн, ωн, sн), breakdown (Mmax; Mк) and critical (sk, sm; sк) values, its
    # synchronous and own speeds (ωs; ωдв, ωmot), its rotor (Jrot; Jрот); a clutch's driving half (Jcl, Mcl, ωd;
    # Jмуф, Mмуф, ωд); a brake (Mt).  A machine's natural frequency on its mounts (ωn).
    r"|(?P<base22>M)(?P<index22>max|cl|муф|[Ntнк])|(?P<base23>s)(?P<index23>[kmNкн])"
    r"|(?P<base24>ω)(?P<index24>mot|дв|[sNdnнд])|(?P<base25>J)(?P<index25>rot|cl|рот|муф)"
    # A rotor's balancing: a mass-radius product (m1r1, mArA, mi·ri, mb·rb), a plane's share of one ((m1r1)L, the
    # table's (m·r)L), a correction mass (mL, mb) and a plane's place along the axis (zR, zi).  The products are two
    # symbols each, m and r with one index, and a share's plane indexes its closing parenthesis.
    # A name running on past a hyphen (a plane A-A) is no index of these: its product is written (m·r)A-A, flat.
    rf"|\((?P<share28>m(?P<index28>{_ROTOR})·?r(?P=index28)|m·r)\)(?P<plane28>{_ROTOR})(?!-)"
    rf"|m(?P<index29>{_ROTOR})(?P<dot29>·?)r(?P=index29)(?!-)"
    rf"|(?P<base30>m)(?P<index30>[{CAPITALS}][A-Za-z0-9]{{0,2}}|b)(?!-)|(?P<base31>z)(?P<index31>[{CAPITALS}]|i)"
    # An index ends where a word would go on: Mс is a symbol, Mсила would be no word of a Russian note.
    r")(?![A-Za-z0-9_А-Яа-яЁё])")

# A plan's letters, small as its points' names are capital, in any of the alphabets a scene may name them in.
_SMALL = "a-zа-яёα-ω"

# A point's name with its link's number below, as the drawings letter it: a mechanism's point standing alone (A4, Σ6;
# a spring's free length L0 and a motor's stall torque M0 alike), and a plan's, whose vectors run their points' names
# together: ps2 (from the pole p to s₂), pa4, b4k5, πn3, pσ6, n6′.  A plan's run is of at most three points with a
# number in it, standing whole, so that no word of the note's languages and no number (1e2) is taken for one; a
# mechanism's point is one capital alone, so that an integrator's name (RK45, DOP853) is none.  An arm of an inertia
# force (hu4) is the drawings' own shape, not the vector from h to u₄.
NUMBERED_POINTS = re.compile(rf"(?<![\w.′″])(?:[{CAPITALS}]\d+[′″]*|(?!h[uи]\d)(?=[{_SMALL}′″]*\d)(?:[{_SMALL}]\d*[′″]*){{1,3}})"
                             r"(?![\w])")
_POINT = re.compile(rf"([{CAPITALS}{_SMALL}])(\d*)([′″]*)")

# Superscript letters stand for the component they show: aBAⁿ is aBA with an n above.
_SUPERSCRIPT = {"ⁿ": "n", "ᵏ": "k", "ʳ": "r"}


class Symbol(NamedTuple):
    """A symbol split into what is set on the line, below it and above it (the latter two may be empty)."""

    base: str
    index: str
    component: str


def _symbol(match: re.Match[str]) -> Symbol:
    groups = {key: value for key, value in match.groupdict().items() if value is not None}
    base = next(value for key, value in groups.items() if key.startswith("base"))
    index = next((value for key, value in groups.items() if key.startswith("index")), "")
    component = next((value for key, value in groups.items() if key.startswith("component")), "")
    return Symbol(base, index, _SUPERSCRIPT.get(component, component.removeprefix("^")))


def _symbols(match: re.Match[str]) -> Iterator[str | Symbol]:
    """A match's symbol, or a rotor's product as its two (m₁r₁, m_i·r_i), a share's in its indexed parentheses."""
    if match["plane28"] is not None:
        yield "("
        yield from _product(match["index28"], match["share28"])
        yield Symbol(")", match["plane28"], "")
    elif match["index29"] is not None:
        yield from _product(match["index29"], match[0])
    else:
        yield _symbol(match)


def _product(index: str | None, written: str) -> Iterator[str | Symbol]:
    """A mass-radius product written as ``mIrI`` or ``mI·rI`` as m and r each with ``index``; ``m·r`` has none."""
    if index is None:
        yield written
        return
    yield Symbol("m", index, "")
    if "·" in written:
        yield "·"
    yield Symbol("r", index, "")


def _numbered_points(written: str) -> Iterator[str | Symbol]:
    """A point or a plan's vector as its points, each numbered one a symbol with its number below: ps2 as p and s₂."""
    for letter, number, primes in _POINT.findall(written):
        yield Symbol(letter, number, "") if number else letter
        if primes:
            yield primes


def pieces(text: str, verbatim: Collection[str] = ()) -> Iterator[str | Symbol]:
    """``text`` as its plain runs (str) and its symbols (:class:`Symbol`), in order; nothing is left out.

    ``verbatim``: the user's own texts (a title, a ``[project]`` value) wherever they stand whole in ``text`` are
    plain runs: a title "Press F1" is no force F with an index 1.
    """
    return iter(_pieces(text, tuple(verbatim)))


# Remembered: the HTML, the LaTeX and the Word document set the same texts (the note's, the tables'), most of them
# many times over (a column's heading on every row), and each was scanned with the symbols' long pattern afresh.
@functools.lru_cache(maxsize=8192)
def _pieces(text: str, verbatim: tuple[str, ...]) -> tuple[str | Symbol, ...]:
    kept = [found.span() for found in occurrences(verbatim).finditer(text)] if verbatim else []
    symbols = [match for match in SYMBOL.finditer(text) if not _overlaps(match, kept)]
    taken = kept + [match.span() for match in symbols]
    points = [match for match in NUMBERED_POINTS.finditer(text) if not _overlaps(match, taken)]
    found: list[str | Symbol] = []
    done = 0
    for match in sorted(symbols + points, key=lambda match: match.start()):
        if match.start() > done:
            found.append(text[done:match.start()])
        found.extend(_symbols(match) if match.re is SYMBOL else _numbered_points(match[0]))
        done = match.end()
    if done < len(text):
        found.append(text[done:])
    return tuple(found)


def _overlaps(match: re.Match[str], spans: Collection[tuple[int, int]]) -> bool:
    return any(start < match.end() and match.start() < end for start, end in spans)


@functools.lru_cache(maxsize=16)
def occurrences(verbatim: tuple[str, ...]) -> re.Pattern[str]:
    """A pattern of the texts ``verbatim``, each standing whole: a title "M" is not the M of the symbol M12."""
    return re.compile("|".join(rf"(?<!\w){re.escape(typed)}(?!\w)"
                               for typed in sorted(filter(None, verbatim), key=len, reverse=True)) or "(?!)")
