"""Values worked out once and given again.

An analysis or a motion holds arrays, so it cannot be a dictionary key: it is
known by its id.  An id is reused once its object is gone, so each entry is
given up when its owner goes (``weakref.finalize``), and a new object with an
old id never finds the old object's values (:class:`OwnedMemo`).  Values keyed
by what they are made of (a label placement, a grown union of lines) have no
owner to outlive, and are kept a bounded number at a time (:class:`RecentMemo`).
"""

from __future__ import annotations

import weakref
from collections import OrderedDict
from collections.abc import Callable, Hashable
from typing import Generic, TypeVar

T = TypeVar("T")


class OwnedMemo(Generic[T]):
    """Values by (owner, key), each made once while its owner lives."""

    def __init__(self) -> None:
        self._values: dict[tuple[int, Hashable], T] = {}
        # The owners watched for their end: looking for one among the values took a hundredth of a test run.
        self._owners: set[int] = set()

    def get(self, owner: object, key: Hashable, make: Callable[[], T]) -> T:
        """The value for ``owner`` and ``key``: ``make()`` the first time, the same value after."""
        entry = (id(owner), key)
        if entry not in self._values:
            value = make()
            if entry[0] not in self._owners:
                self._owners.add(entry[0])
                weakref.finalize(owner, self._forget, entry[0])
            self._values[entry] = value
        return self._values[entry]

    def __len__(self) -> int:
        return len(self._values)

    def _forget(self, owner_id: int) -> None:
        self._owners.discard(owner_id)
        for entry in [entry for entry in self._values if entry[0] == owner_id]:
            del self._values[entry]


class RecentMemo(Generic[T]):
    """Values by key, the ``most`` asked for last kept, the least recently asked given up first."""

    def __init__(self) -> None:
        self._values: OrderedDict[Hashable, T] = OrderedDict()

    def get(self, key: Hashable, make: Callable[[], T], most: int) -> T:
        """The value for ``key``: ``make()`` the first time, the same value after while it is kept."""
        if key in self._values:
            self._values.move_to_end(key)
            return self._values[key]
        value = self._values[key] = make()
        while len(self._values) > most:
            self._values.popitem(last=False)
        return value

    def __len__(self) -> int:
        return len(self._values)


__all__ = ["OwnedMemo", "RecentMemo"]
