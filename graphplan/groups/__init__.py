"""Group kinds by name: adding a kind is one module and one line here."""

from __future__ import annotations

import importlib
from collections.abc import Iterator, Mapping

from .base import Group, Guide
from .driver import Crank, Slider

DRIVERS: dict[str, type[Crank | Slider]] = {"crank": Crank, "slider": Slider}


class _Kinds(Mapping[str, type[Group]]):
    """The group kinds by name (``Group.kind``), each kind's module (``module:Class``) imported when the kind is first
    asked for: a scene of RRR groups loads none of the other kinds' solvers, some 6 ms of a cold run."""

    def __init__(self, where: dict[str, str]) -> None:
        self._where = where

    def __getitem__(self, kind: str) -> type[Group]:
        module, name = self._where[kind].split(":")
        return getattr(importlib.import_module(f".{module}", __name__), name)

    def __iter__(self) -> Iterator[str]:
        return iter(self._where)

    def __len__(self) -> int:
        return len(self._where)


GROUPS: Mapping[str, type[Group]] = _Kinds({"RRR": "rrr:RRR", "RRP": "rrp:RRP", "RPR": "rpr:RPR", "PRP": "prp:PRP",
                                            "RPP": "rpp:RPP", "triad": "triad:Triad"})

Driver = Crank | Slider

__all__ = ["DRIVERS", "GROUPS", "Crank", "Driver", "Group", "Guide", "Slider"]
