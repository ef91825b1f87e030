"""Commented starter scenes for ``graphplan new KIND``: a working mechanism to change into one's own."""

from __future__ import annotations

import difflib
import re
from importlib import resources

from .choices import LOCALES
from .locale import strings

# The kinds a newcomer starts from, each a scene under ``templates/``: mechanisms, and machines known without
# a linkage (a flywheel from its load diagrams, a rotor to balance on its mounts).
MECHANISMS = ("crank-rocker", "slider-crank", "slotted-lever", "shaper", "triad")
MACHINES = ("flywheel", "rotor")
KINDS = MECHANISMS + MACHINES

# The names a starter gives that its drawings and note print as words ("∥ ram"), each under its locale key: the
# frame lines. Points and links are letters and numbers, which every language writes alike.
_NAMED_WORDS = {"ram": "starter_line_ram"}


def starter(kind: str, locale: str = "en") -> str:
    """The commented scene of ``kind`` (one of :data:`KINDS`), its drawings and note in ``locale``: its title and
    the names its note prints in that language (its comments stay English).  The TOML text that ``graphplan new
    KIND --locale LOCALE`` writes, for :func:`graphplan.load_text` (the kinds are ``graphplan.starters.KINDS``)::

        shaper = graphplan.load_text(graphplan.starter("shaper", "ru"))
        shaper.plan(3).values["VA4A3"]   # the slider's velocity along the rocker, m/s
    """
    for name, value, known in (("kind", kind, KINDS), ("locale", locale, LOCALES)):
        if not isinstance(value, str):
            raise TypeError(f"a starter's {name} is one of {', '.join(known)} (got {value!r})")
        if value not in known:
            # slider_crank and Shaper are the kinds slider-crank and shaper, as a command line's kind is typed.
            near = difflib.get_close_matches(value.casefold().replace("_", "-").replace(" ", "-"), known, n=1)
            hint = f"; did you mean {near[0]!r}?" if near else ""
            raise ValueError(f"no starter scene {value!r}; there are {', '.join(known)}{hint}" if name == "kind"
                             else f"no locale {value!r}; there are {', '.join(known)}{hint}")
    text = resources.files("graphplan").joinpath("templates", f"{kind}.toml").read_text(encoding="utf-8")
    words = strings(locale)
    text = re.sub(r'^(title\s*=\s*)"[^"]*"', lambda title: f'{title[1]}"{words[_title_key(kind)]}"', text, count=1,
                  flags=re.MULTILINE)
    for name, key in _NAMED_WORDS.items():
        if words[key] != name:
            text = "\n".join(_renamed(line, name, words[key]) for line in text.split("\n"))
    # The [project] table to fill in shows names as that language writes them (Иванов И. И., 张三).
    for field in ("author", "checked_by", "organization", "designation"):
        text = re.sub(rf'^(# {field}\s*=\s*)"[^"]*"', lambda line, f=field: f'{line[1]}"{words["starter_project_" + f]}"',
                      text, count=1, flags=re.MULTILINE)
    return re.sub(r'^(locale\s*=\s*)"en"', rf'\1"{locale}"', text, count=1, flags=re.MULTILINE)


def _title_key(kind: str) -> str:
    return "starter_title_" + kind.replace("-", "_")


def _renamed(line: str, name: str, word: str) -> str:
    """``line`` of a starter with the name ``name`` written ``word`` where the scene reads it, as a key
    (``ram = {``, quoted, since a bare TOML key is ASCII) or a string (``"ram"``); its comment stays English."""
    code, hash_, comment = line.partition("#")
    code = re.sub(rf'(?<![\w"]){re.escape(name)}(?=\s*=)', f'"{word}"', code)
    code = code.replace(f'"{name}"', f'"{word}"')
    return code + hash_ + comment
