"""Typed access to a parsed TOML table that knows its own key path.

Every value a scene supplies is taken through a :class:`Table`, so that each
error names the exact key (``groups[0].lengths[1]``), what was expected and
what was found, and so that a key nobody took is reported as unknown with the
nearest valid key suggested.
"""

from __future__ import annotations

import datetime
import difflib
import functools
import json
import math
import re
import unicodedata
from collections.abc import Callable, Iterator, Mapping
from typing import Any

from .errors import SceneError, as_written
from .lookalikes import lookalike_hint, plain
from .table_keys import TABLE_KEYS
from .units import RPM, STANDARD_GRAVITY

_REQUIRED = object()

# The symbols a textbook writes a speed under, by the kind of key that takes it here: n is a Russian textbook's
# speed in об/мин, ω (w where it cannot be typed) the angular velocity.
_SPEED_SYMBOLS = {"n": "rpm", "об/мин": "rpm", "обмин": "rpm", "rev/min": "rpm", "ω": "omega", "w": "omega"}


def _type_name(value: object) -> str:
    if isinstance(value, datetime.datetime):
        return "a date-time"
    if isinstance(value, datetime.date):
        return "a date"
    if isinstance(value, datetime.time):
        return "a time"
    if isinstance(value, bool):
        return "a boolean"
    if isinstance(value, int):
        return "an integer"
    if isinstance(value, float):
        return "a number"
    if isinstance(value, str):
        return "a string"
    if isinstance(value, list):
        return "a list"
    if isinstance(value, dict):
        return "a table"
    return type(value).__name__


def join_path(path: str, key: str | int) -> str:
    """The key path of ``key`` inside ``path``: ``a.b``, ``a[0]``."""
    if isinstance(key, int):
        return f"{path}[{key}]"
    if not key or any(mark in key for mark in ' ."\'[]=#\t'):
        # Quoted as TOML quotes it, so that an empty name or one with a dot still reads as one key.
        key = json.dumps(key, ensure_ascii=False)
    return f"{path}.{key}" if path else key


# Control characters a string may hold: the tab and the line breaks of a multi-line """…""" string, which XML and
# LaTeX take.  Every other one (a form feed, a backspace, a bell) makes a sheet's SVG XML that does not parse.
_HARMLESS_CONTROLS = frozenset("\t\n\r")
_CONTROL_NAMES = {"\0": "a null", "\a": "a bell", "\b": "a backspace", "\f": "a form feed", "\v": "a vertical tab",
                  "\x1b": "an escape"}


def refuse_control_characters(value: Any, where: str) -> None:
    """Refuse a string or key anywhere under ``value`` that holds a control character no drawing can hold.

    TOML lets "\\f" and "\\b" stand for a form feed and a backspace, so a Windows path pasted into a "…" string
    ("D:\\files\\fourbar") parses, and writes sheets no browser opens.
    """
    if isinstance(value, dict):
        for key, item in value.items():
            _refuse_in_string(key, where, key=True)
            refuse_control_characters(item, join_path(where, key))
    elif isinstance(value, list):
        for index, item in enumerate(value):
            refuse_control_characters(item, join_path(where, index))
    elif isinstance(value, str):
        _refuse_in_string(value, where, key=False)


def _refuse_in_string(text: str, where: str, *, key: bool) -> None:
    bad = next((c for c in text if unicodedata.category(c) == "Cc" and c not in _HARMLESS_CONTROLS), None)
    if bad is None:
        return
    what = f"{_CONTROL_NAMES.get(bad, 'a control character')} (U+{ord(bad):04X})"
    hint = ""
    if bad in "\b\f":
        hint = (f"; a backslash in a TOML \"…\" string starts an escape (\\{'b' if bad == chr(8) else 'f'} is "
                f"{_CONTROL_NAMES[bad]}): in a path write / for \\, or use a literal '…' string, which takes "
                "backslashes as they are")
    problem = f"{'the key ' + repr(text) + ' ' if key else ''}holds {what}, which no drawing or note can show"
    raise SceneError(where, problem, *(() if key else (text,)), hint=hint)


# The magnitudes a scene may give: beyond them a square overflows or a length vanishes into rounding.
LARGEST = 1e15
SMALLEST = 1e-15


def radians_within_a_turn(degrees: float) -> float:
    """An angle a scene gives in degrees, in radians: its whole turns taken off in degrees first, where that is exact
    (``fmod``), for in radians an angle of many turns keeps only the digits its size leaves after the point, and a
    direction or position would stand off the angle the drawings and results.json write for it."""
    return math.radians(math.fmod(degrees, 360.0))


def check_number(value: Any, where: str, positive: bool = False) -> float:
    """``value`` as a finite float of a magnitude graphplan computes with, or a SceneError naming ``where``; where
    it must be ``positive``, 0 is not offered."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise SceneError(where, f"must be a number, not {_type_name(value)}", value, hint=_number_in_text(value))
    try:
        number = float(value)
    except OverflowError:
        raise SceneError(where, "must be a finite number (got an integer too large for a float)") from None
    if not math.isfinite(number):
        raise SceneError(where, "must be a finite number", value)
    if number != 0 and not SMALLEST <= abs(number) <= LARGEST:
        # "must be 0 or …" of a key that refuses 0 ("must be > 0") offered what it then refused.
        sign = "> 0, " if positive else "0 or "
        raise SceneError(where, f"must be {sign}of a magnitude from {SMALLEST:g} to {LARGEST:g}", value)
    return number


_COMMA_DECIMAL = re.compile(r"[-+]?\d+,\d+")


def _number_in_text(value: Any) -> str:
    """The hint for a number written as a string: in quotes (``"0.175"``), or with the decimal comma a Russian
    text takes (``"0,175"``)."""
    if not isinstance(value, str):
        return ""
    text = value.strip()
    if _COMMA_DECIMAL.fullmatch(text):
        return f"; a decimal comma? TOML numbers take a point and no quotes: write {text.replace(',', '.')}"
    percent = text.endswith("%")
    try:
        number = float(text[:-1] if percent else text)
    except ValueError:
        return ""
    # "inf" and "nan" read as floats too, and are no number a scene means.
    if not math.isfinite(number):
        return ""
    if percent:
        # "15%", a coefficient or a share as a handbook prints it: no scene key is in per cent, each takes the fraction.
        return f"; TOML numbers take no quotes and no % sign: {number:g} % is written {number / 100:g}"
    return _UNQUOTED.format(text=text)


_UNQUOTED = "; TOML numbers take no quotes: write {text}"


def decimal_comma_hint(value: Any, length: int) -> str:
    """The hint for a list of ``length`` numbers that has more, which decimal commas give: TOML reads
    ``[0,55, 0,325]`` as the four integers 0, 55, 0, 325.  Each way of pairing integers back into numbers that
    makes ``length`` of them is offered (two at most: beyond that the list is no slip of a comma)."""
    if not isinstance(value, list) or len(value) <= length:
        return ""
    readings = _comma_readings(value, length)
    if not readings or len(readings) > 2:
        return ""
    written = " or ".join("[" + ", ".join(reading) + "]" for reading in readings)
    return f"; a decimal comma? TOML reads a comma in a list as the next entry: write {written}"


def _comma_readings(items: list[Any], count: int) -> list[list[str]]:
    """Every way ``items`` read as ``count`` numbers, each an item or two integers joined by a decimal point."""
    if count == 0 or not items:
        return [[]] if count == 0 and not items else []
    readings = []
    if isinstance(items[0], int | float) and not isinstance(items[0], bool):
        readings += [[repr(items[0]), *rest] for rest in _comma_readings(items[1:], count - 1)]
    whole, fraction = items[0], items[1] if len(items) > 1 else None
    if all(isinstance(part, int) and not isinstance(part, bool) for part in (whole, fraction)) and fraction >= 0:
        readings += [[f"{whole}.{fraction}", *rest] for rest in _comma_readings(items[2:], count - 1)]
    return readings


def check_int(value: Any, where: str) -> int:
    if isinstance(value, bool) or not isinstance(value, int):
        quoted = isinstance(value, str) and re.fullmatch(r"[-+]?\d+", value.strip()) is not None
        raise SceneError(where, f"must be an integer, not {_type_name(value)}", value,
                         hint=_UNQUOTED.format(text=value.strip()) if quoted else "")
    return value


def check_str(value: Any, where: str) -> str:
    if not isinstance(value, str):
        raise SceneError(where, f"must be a string, not {_type_name(value)}", value)
    if not value.strip():
        raise SceneError(where, "must not be empty")
    return value


def check_xy(value: Any, where: str) -> tuple[float, float]:
    """A point given as ``[x, y]``."""
    if not isinstance(value, list) or len(value) != 2:
        raise SceneError(where, "must be a point [x, y]", value, hint=decimal_comma_hint(value, 2))
    return (check_number(value[0], join_path(where, 0)), check_number(value[1], join_path(where, 1)))


def check_choice(value: Any, where: str, choices: tuple[str, ...]) -> str:
    text = check_str(value, where)
    if text not in choices:
        # A choice in look-alike letters (a Cyrillic о in "forward") reads on screen as the one it is told of.
        raise SceneError(where, f"must be one of {', '.join(choices)}{suggestion(text, choices)}", value,
                         hint=lookalike_hint(text, choices))
    return text


def check_choices(values: Any, where: str, choices: tuple[str, ...], noun: str) -> list[str]:
    """Each of ``values`` one of ``choices`` (``where[k]`` naming the one that is not), and none listed twice: a
    repeat is most likely a slip for another choice, which would then be left out without a word (``noun`` names
    what is listed: "piece", "format")."""
    chosen: list[str] = []
    for k, value in enumerate(values):
        choice = check_choice(value, f"{where}[{k}]", choices)
        if choice in chosen:
            raise SceneError(f"{where}[{k}]", f"{choice} is already listed at {where}[{chosen.index(choice)}]: list "
                             f"each {noun} once", value)
        chosen.append(choice)
    return chosen


# Words people write for a value that has a shorter name here.
ALIASES = {"clockwise": "cw", "anticlockwise": "ccw", "counterclockwise": "ccw", "counter-clockwise": "ccw",
           "anti-clockwise": "ccw",
           # A Russian student's words for the plans measured by hand.
           "скорость": "velocity", "скорости": "velocity", "ускорение": "acceleration", "ускорения": "acceleration",
           "силы": "forces", "реакции": "forces",
           # Languages by the names and country codes people write for them.
           "cn": "zh", "zh-cn": "zh", "zh_cn": "zh", "zh-hans": "zh", "chinese": "zh", "中文": "zh", "汉语": "zh",
           "ru-ru": "ru", "ru_ru": "ru", "russian": "ru", "русский": "ru", "рус": "ru",
           "en-us": "en", "en_us": "en", "en-gb": "en", "en_gb": "en", "english": "en",
           # Keys by the textbook's symbols and by the American spelling; each meets only the key it names.
           "center": "centre", "j": "inertia", "m": "mass", "g": "gravity", "language": "locale", "lang": "locale",
           "r": "length", "l": "length",
           # The moment of inertia about the centre of mass as the textbooks write it (J_S, I_S).
           "js": "inertia", "j_s": "inertia", "is": "inertia", "i_s": "inertia", "i": "inertia",
           # An induction motor by the names a catalogue and a Russian textbook give it: its characteristic is Kloss'.
           "induction": "kloss", "asynchronous": "kloss", "async": "kloss", "асинхронный": "kloss", "клосс": "kloss",
           # A load's kind by its other names: "torque" was told "did you mean 'force'?" by its letters.
           "torque": "moment", "couple": "moment", "момент": "moment", "сила": "force", "力矩": "moment", "力": "force"}


def suggestion(word: str, choices: Any) -> str:
    """"; did you mean 'ru'?" naming the choice ``word`` stands for (in other capitals or look-alike letters, by an
    alias, or spelt near it), or "" where none is near: for the scene's keys and choices and the command line's."""
    names = [str(c) for c in choices]
    lowered = word.strip().lower()
    alias = lowered if lowered in names else ALIASES.get(lowered)
    # Capitals or small letters, and letters that look the same in another script (a Cyrillic А1 for A1).
    folded = {plain(name).casefold(): name for name in names}
    alias = alias if alias in names else folded.get(plain(word.strip()).casefold())
    if alias in names:
        return f"; did you mean {alias!r}?"
    # Two letters that share one with a name are half alike: de (German) was "did you mean 'en'?".
    short = len(word.strip()) <= 2
    close = difflib.get_close_matches(word, names, n=1, cutoff=0.51 if short else 0.5) \
        or [name for name in names if _swapped(lowered, name.lower())]
    return f"; did you mean {close[0]!r}?" if close else ""


# How alike a key of several other tables must be to one of the table it is written in to be asked about it: mass
# is masses (0.8), count is not joint (0.6).
_ALMOST_THE_SAME = 0.75


def _swapped(typed: str, key: str) -> bool:
    """``typed`` is ``key`` with two letters side by side swapped (rmp for rpm), which the similarity ratio of a
    short key counts as far off as another key."""
    return len(typed) == len(key) and typed != key and any(
        typed == key[:at] + key[at + 1] + key[at] + key[at + 2:] for at in range(len(key) - 1))


# What each required key is for, by its key path (``[]`` for any index, ``*`` for any one name): "is required but
# missing" alone left a student who had not met the key guessing what to write.
_GUIDE = "the line the slider moves along: a frame line's name, or { through = [x, y], angle = degrees }"
_THROUGH = "a point the line runs through: [x, y], or a point's name"
_SENSE = ("ccw or cw for a turning link, forward or backward (along its guide) for a sliding one: its motion in the "
          "stroke")
REQUIRED_PURPOSES = {
    "frame": "the fixed link's table: link = 1 and its points, points = { O = [x, y], … }",
    "driver": "the input link's table: kind = \"crank\" or \"slider\", its link, joint and speed",
    "driver.kind": "crank (the input link turns about a frame point) or slider (it moves along a guide)",
    "driver.link": "the number of the input link, as on the kinematic scheme",
    "driver.pivot": "the frame point the crank turns about",
    "driver.joint": "the joint the input link moves, at its end, where the first group joins on",
    "driver.length": "the crank's length from pivot to joint, m",
    "driver.guide": _GUIDE,
    "driver.velocity": "the slider's velocity along its guide, m/s",
    "driver.travel": "[s0, s1], the stroke the positions run over, m along the guide from its through point",
    "driver.guide.through": _THROUGH,
    "groups[].guide.through": _THROUGH,
    "groups[].guides[].through": _THROUGH,
    "frame.lines.*.through": _THROUGH,
    "groups[].kind": "the group's kind: RRR, RRP, RPR, PRP, RPP or triad",
    "groups[].links": "the numbers of the group's links, as on the kinematic scheme",
    "groups[].joints": "the names of the group's joints, its outer ones known from the driver or a group before it",
    "groups[].lengths": "the lengths of the group's links between its joints, m, in the order its kind lists them",
    "groups[].length": "lAB, the length of link a from its outer joint A to the slider's joint B, m",
    "groups[].guide": _GUIDE,
    "groups[].guides": "[g1, g2], the lines the two sliders move along",
    "groups[].sides": "[BD, DF, FB], the ternary link's sides, m",
    "groups[].near": "where each inner joint lies in a sketch, { B = [x, y], D = [x, y], F = [x, y] }, which chooses "
                     "among up to six assemblies",
    "points.*.link": "the number of the link the point is fixed on",
    "points.*.from": "the point it is placed from, at metres along from→toward",
    "points.*.toward": "the point that gives, from `from`, the direction the point is placed along",
    "points.*.at": "how far the point lies from `from` toward `toward`, m",
    "loads[].kind": "moment (a couple on its link) or force (at a point of its link)",
    "loads[].link": "the number of the link the load acts on",
    "loads[].point": "a force needs point, where it acts: a point fixed on its link (a joint or one of [points])",
    "loads[].angle": "a force needs angle, its direction in degrees from +x (counter-clockwise), or along, the point "
                     "whose line to its point it acts along",
    "loads[].value": "the load's size, N·m for a moment, N for a force (or a diagram in its place)",
    "loads[].stiffness": "a spring's stiffness k, N/m (its force k·(L − L0), pulling its ends together where longer)",
    "loads[].free_length": "a spring's free length L0, m, at which it neither pushes nor pulls",
    "loads[].during.from": "the share of the working stroke (0 to 1) where the load begins to act",
    "loads[].during.to": "the share of the working stroke (0 to 1) where the load stops acting",
    "loads[].stroke.link": "the number of the link whose motion makes the load's stroke",
    "loads[].stroke.sense": _SENSE,
    "positions.working.link": "the number of the link whose motion makes the working stroke",
    "positions.working.sense": _SENSE,
    "friction[].joint": "the joint whose pair the friction acts in",
    "balancing.masses": "the rotor's masses, a list of { mass, radius, angle }",
    "balancing.masses[].mass": "the mass, kg",
    "balancing.masses[].radius": "its distance from the axis, m",
    "balancing.masses[].angle": "its direction about the axis, degrees",
    "dynamics.motor": "the motor's table: kind and its characteristic",
    "dynamics.motor.kind": "the motor's characteristic: constant, linear or kloss",
    "dynamics.motor.torque": "the motor's torque, N·m",
    "dynamics.motor.stall_torque": "the linear characteristic's torque at rest, N·m",
    "dynamics.motor.no_load_rpm": "the linear characteristic's speed where its torque is 0, rev/min",
    "dynamics.motor.power": "the motor's rated power, W",
    "dynamics.motor.overload": "the ratio Mmax/Mrated of the motor's torques (above 1)",
    "dynamics.clutch.torque": "the torque the clutch passes at most, N·m",
    "vibration.mass": "the machine's mass on its mounts, kg",
    "vibration.shaft.modulus": "the shaft's Young's modulus, Pa",
    "vibration.shaft.length": "the shaft's length between its bearings, m",
}


def required_purpose(where: str) -> str:
    """": what the key is for" of the required key at ``where``, or "" where none is written down."""
    shape = re.sub(r"\[\d+\]", "[]", where)
    for pattern, purpose in REQUIRED_PURPOSES.items():
        if re.fullmatch(re.escape(pattern).replace(r"\*", r"[^.]+"), shape):
            return f": {purpose}"
    return ""


class Table:
    """A TOML table being read: each key is taken once, the rest are unknown.

    Parameters
    ----------
    data
        The table as :mod:`tomllib` parsed it.
    path
        Its key path, used as the prefix of every error message.
    """

    def __init__(self, data: Any, path: str) -> None:
        if not isinstance(data, dict):
            raise SceneError(path, f"must be a table, not {_type_name(data)}", data)
        self.data = data
        self.path = path
        self._taken: set[str] = set()

    def where(self, key: str | int) -> str:
        return join_path(self.path, key)

    def has(self, key: str) -> bool:
        return key in self.data

    def raw(self, key: str, default: Any = _REQUIRED) -> Any:
        """The value of ``key`` unchecked; a missing required key is an error."""
        self._taken.add(key)
        if key in self.data:
            return self.data[key]
        if default is _REQUIRED:
            self.misspelt(key)
            raise SceneError(self.where(key), f"is required but missing{required_purpose(self.where(key))}")
        return default

    def misspelt(self, *keys: str) -> None:
        """A required key that is missing is often there, misspelt: name the misspelling of one of ``keys``."""
        strangers = [k for k in self.data if k not in self._taken]
        for key in keys:
            if key == "mass":
                self._weight_for_mass(strangers)
            close = [k for k in strangers if k.lower() == key.lower() or ALIASES.get(k.strip().lower()) == key] \
                or difflib.get_close_matches(key, strangers, n=1, cutoff=0.7) \
                or [k for k in strangers if _swapped(k.lower(), key.lower())]
            if close:
                raise SceneError(self.where(close[0]), f"unknown key; did you mean {key!r}?")

    def _weight_for_mass(self, strangers: list[str]) -> None:
        """A weight given where the mass is asked for: named with the mass it stands for, as a weight in N is no
        mass in kg ("did you mean 'mass'?" alone would have the newtons typed as kilograms)."""
        for key in strangers:
            if key.strip().lower() in ("weight", "w"):
                value = self.data[key]
                number = value if isinstance(value, int | float) and not isinstance(value, bool) else None
                meant = f" = {number / STANDARD_GRAVITY:.4g}" if number is not None else " = W/g"
                raise SceneError(self.where(key), "unknown key; the mass is given as mass, in kg: a weight W in N is "
                                 f"mass = W/g (g = {STANDARD_GRAVITY} m/s²), here mass{meant}")

    def named_otherwise(self, key: str, names: frozenset[str], what: str) -> None:
        """A key that is another name people use for ``key`` (μ, mu or coefficient for a friction coefficient's
        f) named with the one to write, before ``key`` is missed (or with its value, where it is given too).
        ``names`` are lower case; ``what`` says what the value is."""
        for other in self.data:
            if other not in self._taken and other.strip().casefold() in names:
                if key in self.data:
                    raise SceneError(self.where(other), f"unknown key; {what} is given as {key}, which this table "
                                     f"has already: {key} = {as_written(self.data[key])}")
                raise SceneError(self.where(other), f"unknown key; {what} is given as {key}: write "
                                 f"{key} = {as_written(self.data[other])}")

    def _misplaced(self, key: str, home: str) -> None:
        """Raise at ``key``, a key of the table ``home`` (nested in this one, or this one's owner), saying how to
        write it there."""
        value = f"{key} = {as_written(self.data[key])}"
        if "." not in home and not self.path.startswith(home + "."):  # a table of the scene's own, from another
            how = f"write it under [{home}]: {value}"
        elif self.path.startswith(home + "."):
            how = f"write it under [{home}], not inside {self.path.removeprefix(home + '.')} = {{ … }}: {value}"
        else:  # nested in this table, or beside it in their owner
            inside = home.removeprefix(self.path + ".") if home.startswith(self.path + ".") else home.rpartition(".")[2]
            how = f"write it inside {inside} = {{ …, {value} }}"
        raise SceneError(self.where(key), f"unknown key; {key} is a key of {home}, not of {self.path}: {how}")

    def take(self, key: str, default: Any, check: Callable[[Any, str], Any]) -> Any:
        """The value of ``key`` as ``check(value, where)`` returns it, or ``default`` where the key is absent."""
        value = self.raw(key, default)
        if key not in self.data:
            return value
        return check(value, self.where(key))

    def number(self, key: str, default: Any = _REQUIRED, *, positive: bool = False,
               non_negative: bool = False) -> Any:
        value = self.take(key, default, functools.partial(check_number, positive=positive))
        if key in self.data:
            if positive and not value > 0:
                raise SceneError(self.where(key), "must be > 0", self.data[key])
            if non_negative and value < 0:
                raise SceneError(self.where(key), "must be >= 0", self.data[key])
        return value

    def speed(self, default: Any = _REQUIRED, *, omega_key: str = "omega", rpm_key: str = "rpm",
              positive: bool = False, non_negative: bool = False, sense: str = "") -> Any:
        """A speed in rad/s, given in rad/s under ``omega_key`` or in rev/min under ``rpm_key``, not both.

        A required speed that is missing is named by both keys, with ``sense``
        (how it is signed, where it is) after them; so is a negative one where
        it may not be (a size only, whose sense comes from elsewhere).
        """
        if self.has(omega_key) and self.has(rpm_key):
            raise SceneError(self.where(rpm_key), f"give either {omega_key} or {rpm_key}, not both")
        if self.has(rpm_key):
            self._taken.add(omega_key)  # still a valid key, for the did-you-mean of a misspelt one
            return self._speed_size(rpm_key, _REQUIRED, positive, non_negative, sense) * RPM
        self._taken.add(rpm_key)
        if self.has(omega_key):
            return self._speed_size(omega_key, default, positive, non_negative, sense)
        self._speed_symbol(omega_key, rpm_key)
        if default is not _REQUIRED:
            return default
        self.misspelt(omega_key, rpm_key)
        raise SceneError(self.where(omega_key),
                         f"is required but missing: give {omega_key} (rad/s) or {rpm_key} (rev/min){sense}")

    def _speed_symbol(self, omega_key: str, rpm_key: str) -> None:
        """A speed given under a textbook's symbol for it, where neither key is: n (об/мин, as a Russian textbook
        writes the speed in rev/min) or ω, named with the key it is given as here, before the speed is missed."""
        for key in self.data:
            if key not in self._taken and key.strip().lower() in ("rps", "rev/s") and isinstance(self.data[key], int | float):
                raise SceneError(self.where(key), f"unknown key; a speed in rev/s is given in rev/min as {rpm_key}: "
                                 f"write {rpm_key} = {as_written(60 * self.data[key])}")
            meant = _SPEED_SYMBOLS.get(key.strip().lower()) if key not in self._taken else None
            if meant is not None:
                right, unit = (rpm_key, "rev/min") if meant == "rpm" else (omega_key, "rad/s")
                raise SceneError(self.where(key), f"unknown key; a speed in {unit} is given as {right}: "
                                 f"write {right} = {as_written(self.data[key])}")

    def _speed_size(self, key: str, default: Any, positive: bool, non_negative: bool, sense: str) -> Any:
        value = self.number(key, default, positive=positive)
        if non_negative and key in self.data and value < 0:
            raise SceneError(self.where(key), f"must be >= 0{sense}", self.data[key])
        return value

    def integer(self, key: str, default: Any = _REQUIRED, *, minimum: int | None = None,
                maximum: int | None = None) -> Any:
        value = self.take(key, default, check_int)
        if key in self.data:
            if minimum is not None and value < minimum:
                raise SceneError(self.where(key), f"must be >= {minimum}", value)
            if maximum is not None and value > maximum:
                raise SceneError(self.where(key), f"must be <= {maximum}", value)
        return value

    def string(self, key: str, default: Any = _REQUIRED) -> Any:
        return self.take(key, default, check_str)

    def date(self, key: str, default: Any = _REQUIRED) -> Any:
        """A TOML date (``2026-12-01``), or a string for a date written otherwise."""
        def check(value: Any, where: str) -> datetime.date | str:
            # A date-time or a time of day is not the day a drawing is signed on.
            if isinstance(value, datetime.date) and not isinstance(value, datetime.datetime):
                return value
            if isinstance(value, str):
                return check_str(value, where)
            raise SceneError(where, f"must be a date (2026-12-01) or a string, not {_type_name(value)}", value)
        return self.take(key, default, check)

    def boolean(self, key: str, default: Any = _REQUIRED) -> Any:
        def check(value: Any, where: str) -> bool:
            if not isinstance(value, bool):
                raise SceneError(where, f"must be true or false, not {_type_name(value)}", value)
            return value
        return self.take(key, default, check)

    def choice(self, key: str, choices: tuple[str, ...], default: Any = _REQUIRED) -> Any:
        return self.take(key, default, lambda v, w: check_choice(v, w, choices))

    def xy(self, key: str, default: Any = _REQUIRED) -> Any:
        return self.take(key, default, check_xy)

    def table(self, key: str, default: Any = _REQUIRED) -> Table | None:
        value = self.raw(key, default)
        if key not in self.data:
            return value
        return Table(value, self.where(key))

    def items(self, key: str, *, length: int | None = None, default: Any = _REQUIRED) -> list[tuple[str, Any]] | None:
        """A list under ``key`` as ``(path, item)`` pairs, its length checked."""
        value = self.raw(key, default)
        if key not in self.data:
            return value
        where = self.where(key)
        if not isinstance(value, list):
            # The document's lists are of tables: [friction] for [[friction]] makes one table of its entry.
            hint = f"; write [[{key}]] (an array of tables), not [{key}]" if not self.path and isinstance(value, dict) else ""
            raise SceneError(where, f"must be a list, not {_type_name(value)}", value, hint=hint)
        if length is not None and len(value) != length:
            raise SceneError(where, f"must have {length} entries, not {len(value)}", value,
                             hint=decimal_comma_hint(value, length))
        return [(join_path(where, i), item) for i, item in enumerate(value)]

    def numbers(self, key: str, length: int, default: Any = _REQUIRED, *, positive: bool = False) -> Any:
        pairs = self.items(key, length=length, default=default)
        if key not in self.data:
            return pairs  # the default
        result = []
        for where, item in pairs:
            number = check_number(item, where)
            if positive and not number > 0:
                raise SceneError(where, "must be > 0", item)
            result.append(number)
        return tuple(result)

    def names(self, key: str, length: int) -> tuple[str, ...]:
        pairs = self.items(key, length=length)
        assert pairs is not None
        return tuple(check_str(item, where) for where, item in pairs)

    def subtables(self) -> Iterator[tuple[str, Table]]:
        """Every entry of a table of tables (``[links.3]``), keyed by its name."""
        for key in list(self.data):
            yield key, self.table(key)  # type: ignore[misc]

    def _refuse_undeclared(self) -> None:
        """Raise :class:`RuntimeError` where a scene's table (by its path, one of ``TABLE_KEYS``) was read for a key
        table_keys.py does not list: a key added to a reader and not there would be sent elsewhere when written in
        another table, so the first test that reads the table fails, not only tests/test_table_keys_agree.py."""
        declared = TABLE_KEYS.get(self.path)
        undeclared = sorted(self._taken.difference(declared)) if declared is not None else []
        if undeclared:
            raise RuntimeError(f"[{self.path}] was read for {', '.join(undeclared)}, which "
                               f"graphplan/table_keys.py's TABLE_KEYS[{self.path!r}] does not list: add it there")

    def done(self, *, list_known: bool = False, elsewhere: Mapping[str, str | tuple[str, ...]] | None = None) -> None:
        """Reject the first key that nobody took, suggesting the nearest valid one, or with ``list_known`` (a
        table whose keys are all read whatever it holds) every valid one when none is near.

        ``elsewhere`` maps keys of a table nested in this one, or of the one this is nested in, to that table's
        path: such a key here is told where it goes, for the nearest key here would send the user astray
        (``dynamics.gear_ratio`` was asked "did you mean 'duration'?", the motor's key written beside it).  A key
        mapped to several tables (:func:`~graphplan.table_keys.keys_of_other_tables`) is told whose it is, with a
        key of this table only where one is all but the same (masses for mass)."""
        self._refuse_undeclared()
        if "mass" in self._taken:
            self._weight_for_mass([key for key in self.data if key not in self._taken])
        for key in self.data:
            if key not in self._taken and elsewhere and key in elsewhere:
                home = elsewhere[key]
                if isinstance(home, str):
                    self._misplaced(key, home)
                # driver.count was asked "did you mean 'joint'?": a key of two other tables, near none here.
                near = difflib.get_close_matches(key, sorted(self._taken), n=1, cutoff=_ALMOST_THE_SAME)
                raise SceneError(self.where(key), f"unknown key; {key} is a key of {', '.join(home[:-1])} or "
                                 f"{home[-1]}, not of {self.path}" + (f"; did you mean {near[0]!r}?" if near else ""))
            if key not in self._taken:
                hint = suggestion(key, sorted(self._taken))
                if not hint and list_known:
                    hint = f"; the keys here are {', '.join(sorted(self._taken))}"
                raise SceneError(self.where(key), "unknown key" + hint)
