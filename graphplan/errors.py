"""The error hierarchy: every problem a user can cause is one of these.

Each class is also a builtin exception, so callers that know nothing of
graphplan can still catch ``ValueError`` or ``ArithmeticError``.  Messages are
built from structured fields and use the user's own names: the key path of
the scene, the joint, the position.
"""

from __future__ import annotations

import contextlib
import contextvars
import math
from collections.abc import Iterator

# Set while a caller asks only whether a step refuses, not what it says (the reach advice trying swings, whose
# refusals only say to try the next): what a refusal works out only to tell (the reach of a crank, the pole distance
# or a scale that would fit) is left out there.
_VERDICT_ONLY: contextvars.ContextVar[bool] = contextvars.ContextVar("verdict_only", default=False)


@contextlib.contextmanager
def verdict_only() -> Iterator[None]:
    """Within it, a refusal raised is only caught and dropped: its words may leave out what they would offer."""
    token = _VERDICT_ONLY.set(True)
    try:
        yield
    finally:
        _VERDICT_ONLY.reset(token)


def words_wanted() -> bool:
    """Whether a refusal's words will be read (not within :func:`verdict_only`)."""
    return not _VERDICT_ONLY.get()


class GraphplanError(Exception):
    """Base of every error graphplan raises on purpose."""


class SceneError(GraphplanError, ValueError):
    """A scene file that cannot be read or does not describe a mechanism.

    Parameters
    ----------
    where
        The key path, such as ``groups[0].lengths[1]``; empty for the file itself.
    problem
        What is wrong, in words, for instance ``must be > 0``.
    value
        The offending value, shown after the problem when given.
    hint
        What the value was likely meant to be, after it (``"; 'О' has the Cyrillic 'О' …"``): it reads only
        once the value is seen.
    """

    _NO_VALUE = object()

    def __init__(self, where: str, problem: str, value: object = _NO_VALUE, *, hint: str = "") -> None:
        self.where = where
        self.problem = problem
        self.value = value
        self.hint = hint
        message = f"{where}: {problem}" if where else problem
        if value is not SceneError._NO_VALUE:
            message += f" (got {as_written(value)})"
        super().__init__(message + hint)


def as_written(value: object, nested: bool = False) -> str:
    """A scene's value as the scene wrote it: a table as TOML's ``{ from = 0.9, to = 0.1 }`` (Python's dict was
    ``{'from': 0.9, 'to': 0.1}``), a list's items and a table's so too (``kind = "RRR"``, ``true``); a single
    value as Python writes it."""
    if hasattr(value, "isoformat"):
        return value.isoformat()
    if isinstance(value, dict):
        return "{ " + ", ".join(f"{_key(key)} = {as_written(item, True)}" for key, item in value.items()) + " }"
    if isinstance(value, list | tuple):
        return "[" + ", ".join(as_written(item, True) for item in value) + "]"
    if nested and isinstance(value, bool):
        return "true" if value else "false"
    if nested and isinstance(value, str):
        return '"' + value.replace("\\", "\\\\").replace('"', '\\"') + '"'
    if isinstance(value, int) and not isinstance(value, bool) and abs(value) >= _LONGEST_INTEGER_SHOWN:
        # A page of digits hides the message around it (positions.count = 10**400 from Python).
        return f"{'-' if value < 0 else ''}an integer of {_digits(abs(value))} digits"
    return repr(value)


_LONGEST_INTEGER_SHOWN = 10 ** 30


def listed(names: list[str] | tuple[str, ...]) -> str:
    """Names as a sentence lists them: ``A``, ``A and C``, ``A, C and E``."""
    return names[0] if len(names) == 1 else f"{', '.join(names[:-1])} and {names[-1]}"


def _digits(value: int) -> str:
    """How many decimal digits ``value`` has; beyond what Python turns into a string, roughly."""
    try:
        return str(len(str(value)))
    except ValueError:
        return f"about {int(value.bit_length() * math.log10(2)) + 1}"


def _key(key: object) -> str:
    text = str(key)
    return text if text and all(c.isascii() and (c.isalnum() or c in "_-") for c in text) else f'"{text}"'


class AssemblyError(GraphplanError, ValueError):
    """A position the mechanism cannot reach.

    ``position`` says where (``φ = 212°``, or ``position 7 (φ = 212°)``),
    ``group`` names the group (``II(3,4)``), ``joint`` the joint that cannot be
    placed, and ``reason`` the arithmetic that shows why.  ``keys``: the scene's
    keys that set what does not close there (the group's lengths, and what places
    its outer joints), where a scene's run told them; its reason names them too.
    """

    def __init__(self, joint: str, position: str, group: str, reason: str, keys: tuple[str, ...] = ()) -> None:
        self.joint = joint
        self.position = position
        self.group = group
        self.reason = reason
        self.keys = keys
        super().__init__(f"{joint} cannot be assembled at {position} in group {group}: {reason}")


class SingularPositionError(GraphplanError, ArithmeticError):
    """A position where velocities are not determined by the driver's motion.

    At such a position (a toggle: the two lines of action of a group are
    parallel) the velocity equations have no unique solution; graphplan reports
    it instead of guessing.
    """

    def __init__(self, position: str, group: str, reason: str) -> None:
        self.position = position
        self.group = group
        self.reason = reason
        super().__init__(f"singular position at {position} in group {group}: {reason}")


class UnknownNameError(GraphplanError, KeyError):
    """A point, link, sliding pair or reaction asked of a result by a name or number it does not have.

    Also a ``KeyError``, as a mapping's missing key is; the message names what was asked and what there is.
    """

    def __str__(self) -> str:
        # KeyError's own str quotes its message as a key's repr: "\"no point 'Z'; points are …\"".
        return str(self.args[0]) if self.args else ""


class PositionIndexError(GraphplanError, IndexError):
    """Positions picked from a motion by indices it does not have (``motion.at_positions``)."""


class OutputError(GraphplanError, OSError):
    """An output could not be made (a PDF without its typesetter) or the output folder could not be written."""


class FrictionError(GraphplanError, ValueError):
    """A friction or efficiency calculation asked with an argument outside its range.

    ``argument`` is the parameter as the function spells it (``f``,
    ``incline_angle``), ``problem`` says what is wrong (and, for an array,
    at which index), ``value`` is the offending value itself.
    """

    _NO_VALUE = object()

    def __init__(self, argument: str, problem: str, value: object = _NO_VALUE) -> None:
        self.argument = argument
        self.problem = problem
        self.value = value
        message = f"{argument}: {problem}"
        if value is not FrictionError._NO_VALUE:
            message += f" (got {value!r})"
        super().__init__(message)


class SelfLockingError(FrictionError):
    """A driving force, torque or efficiency asked where the pair locks itself.

    The asked motion cannot be driven by any finite force of the given kind
    (the slider jams), so the quantity does not exist; its formula would
    return a meaningless negative or infinite number.
    """
