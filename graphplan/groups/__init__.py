"""Group kinds by name: adding a kind is one module and one line here."""

from __future__ import annotations

from .base import Group, Guide
from .driver import Crank, Slider
from .prp import PRP
from .rpp import RPP
from .rpr import RPR
from .rrp import RRP
from .rrr import RRR
from .triad import Triad

DRIVERS: dict[str, type[Crank | Slider]] = {"crank": Crank, "slider": Slider}
GROUPS: dict[str, type[Group]] = {kind.kind: kind for kind in (RRR, RRP, RPR, PRP, RPP, Triad)}

Driver = Crank | Slider

__all__ = ["DRIVERS", "GROUPS", "Crank", "Driver", "Group", "Guide", "Slider"]
