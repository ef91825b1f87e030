"""The keys each of the scene's tables takes, for the hint of a key written in the wrong one.

A right key in the wrong table was asked about the nearest key of the table it stands in (``frame.pivot``: "did you
mean 'points'?", ``scene.planes``: "did you mean 'locale'?"), which sends the user astray.  The readers of the tables
live in modules that do not import each other (``[driver]`` in ``groups/driver.py`` below ``scene.py``), so the keys
are listed here, a module that imports nothing, for every reader to ask.
"""

from __future__ import annotations

# The tables a key is told to be written under, with every key each takes (whatever its kind or mode).  Written out
# here, not gathered from the readers, which import this module; tests/test_table_keys_agree.py reads scenes of every
# kind and mode and checks that these are the keys the readers take, no more and no fewer.
TABLE_KEYS = {
    "scene": ("title", "locale", "gravity"),
    "project": ("author", "checked_by", "approved_by", "organization", "designation", "date"),
    "frame": ("link", "points", "lines"),
    "driver": ("kind", "link", "pivot", "joint", "length", "omega", "rpm", "epsilon", "swing", "guide", "velocity",
               "acceleration", "travel"),
    "positions": ("count", "start", "number_from", "working", "plans", "velocity_plans"),
    "drawing": ("length_scale", "velocity_pole", "acceleration_pole", "velocity_scale", "acceleration_scale",
                "velocity_plans_pole", "force_scale", "drafting_precision", "sheet"),
    "output": ("include",),
    "forces": ("inertia",),
    "dynamics": ("delta", "rpm", "omega", "flywheel_shaft_rpm", "constant", "count", "motor", "brake", "clutch",
                 "start", "duration", "method", "rtol", "steady_tolerance", "resisting_torque", "resisting_power",
                 "driving_torque", "driving_power", "driving", "resisting", "inertia"),
    "balancing": ("masses", "planes", "plane_names", "correction_radius"),
    "vibration": ("mass", "stiffness", "shaft", "damping_ratio", "damping", "omega", "rpm", "transmissibility",
                  "base_amplitude", "unbalance", "unbalanced_mass", "eccentricity"),
}
# Tables a key is not told to be written under (one of several of their kind: a link's, a group's, a load's), whose
# keys still make a key another table's alone no longer: ``inertia`` is [dynamics]' and [forces]' and a link's.
NUMBERED_TABLE_KEYS = {
    "links.N": ("mass", "centre", "inertia"),
    "[[groups]]": ("kind", "links", "joints", "lengths", "length", "assembly", "near", "guide", "guides", "angle",
                   "offset", "offsets", "sides", "slots"),
    "[[loads]]": ("kind", "link", "point", "value", "angle", "along", "stiffness", "free_length", "resisting", "during",
                  "diagram", "stroke"),
    "[[friction]]": ("joint", "links", "f", "radius", "groove_half_angle"),
    "points.NAME": ("link", "from", "toward", "at", "offset"),
    "measured.N": ("velocity", "acceleration", "forces", "balancing"),
}


def keys_of_other_tables(table: str) -> dict[str, str | tuple[str, ...]]:
    """Each key ``table`` does not take but another of the scene's tables does, for :meth:`Table.done`'s
    ``elsewhere``: with the path of that table where it is the one table that takes it, or with every table that
    takes it where several do (``count``: [positions] and [dynamics]), which names them but tells none to write it
    in.  A key ``table`` takes in another of its kinds or modes is left out: its own reader tells it."""
    homes: dict[str, list[str]] = {}
    for home, keys in (*TABLE_KEYS.items(), *NUMBERED_TABLE_KEYS.items()):
        for key in keys:
            homes.setdefault(key, []).append(home)
    return {key: (where[0] if len(where) == 1 and where[0] in TABLE_KEYS else tuple(where))
            for key, where in homes.items() if table not in where}


__all__ = ["NUMBERED_TABLE_KEYS", "TABLE_KEYS", "keys_of_other_tables"]
