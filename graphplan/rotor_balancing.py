"""Balancing rotating masses by vector polygons: a disc in one plane, a long rotor in two.

A mass m at radius r and angle θ turning with the rotor at ω pulls on its
bearings with the centrifugal force m·r·ω² along θ.  Since ω² is common to
every mass, the textbooks balance the *mass-radius products* m·r (kg·m),
drawn as vectors at their angles.

* **Static balancing** (one correction plane: a disc, a gear, a pulley): the
  correction makes the polygon of m·r close,

      Σ mi·ri + mb·rb = 0,

  so the correction is the closing vector, from the end of the last m·r back
  to the start.

* **Dynamic balancing** (two correction planes L and R at zL and zR along
  the axis): each mass-radius product is first split between the two planes
  by moments about the other plane,

      (mi·ri)L = mi·ri·(zR − zi)/(zR − zL),   (mi·ri)R = mi·ri·(zi − zL)/(zR − zL),

  which keeps both its force (the shares add up to mi·ri) and its moment
  (zL·(mi·ri)L + zR·(mi·ri)R = zi·mi·ri).  A mass between the planes gives
  shares of its own sense in both; one outside them gives a share against
  its sense in the farther plane.  Each plane then closes its own polygon
  as a disc does; the rotor corrected in both planes has neither resultant
  force nor resultant moment.

Conventions: SI units; angles in degrees at the edges (``angle_deg``),
counter-clockwise positive, measured in the rotor's frame from its x-axis;
a mass-radius product in the records is a complex number m·r·e^{iθ} (kg·m).
The records keep each plane's polygon as it is laid out (its vectors head
to tail, the closing correction last), so the drawing
(:mod:`graphplan.render.balancing`) reads what was constructed.
"""

from __future__ import annotations

import cmath
import math
import numbers
import re
from collections.abc import Sequence
from dataclasses import dataclass, replace
from typing import Any

from .errors import SceneError
from .lookalikes import contrast, plain, twin
from .reader import Table, check_number, check_str, join_path
from .rotor_lengths import (
    FLATTEST_ROTOR,
    LARGEST_RADIUS_M,
    LONGEST_ROTOR_M,
    MIXED_RATIO,
    THINNEST_DISC,
    Implausible,
    LengthsInMillimetres,
    bounding_cylinder,
    heaviest_rotor,
    radii_are_eccentricities,
    rotor_length,
    solid_steel_reach,
)
from .rounding import ROUNDING_NOISE, rounded_up, written_as_nought
from .table_keys import keys_of_other_tables

#: A correction below this share of its polygon's perimeter is rounding: the plane needs none, its angle is 0.
NEGLIGIBLE = 1e-12
#: Corrections whose Σ |mb·rb| is more than this many times the masses' own Σ |mi·ri| are cautioned of: the planes are
#: too close for the masses' spread, and the corrections a large couple on a short arm (a mass d beyond planes s apart
#: carries shares of some d/s into them, so 10 is a mass some 4.5 spacings out).
LARGE_CORRECTIONS = 10.0
#: Each polygon is drawn at the standard scale that makes it at most this wide or tall (mm), by render/balancing.py.
POLYGON_FIELD_MM = 90.0
#: The most characters a mass's or a correction plane's name may have.  The names letter the products on the polygons
#: as their indices and after them (m1r1, (m1r1)L; a longer name flat, (m·r)left), beside sides drawn within
#: POLYGON_FIELD_MM, at the names' 3.5 mm lettering some 3 mm a lowercase character: a share's label,
#: ((m·r)impeller)drive end, with ten of each comes to some 70 mm, most of the field, where a plane named by 80
#: characters ran its labels and caption 200 mm past its polygon.  Ten take every name a rotor's plane or part is given
#: (L, R, I–I, left, drive end, impeller; левая, правая).
LONGEST_NAME = 10
#: Names of the correction planes when the scene does not name them.
DYNAMIC_PLANE_NAMES = ("L", "R")
STATIC_PLANE_NAMES = ("b",)


def _finite(argument: str, value: float) -> float:
    if isinstance(value, bool) or not isinstance(value, numbers.Real) or not math.isfinite(value):
        raise ValueError(f"{argument}: must be a finite number (got {value!r})")
    return float(value)


@dataclass(frozen=True)
class RotatingMass:
    """A mass turning with the rotor: ``mass`` (kg) at ``radius`` (m) and ``angle_deg``, in the plane at ``plane`` (m).

    ``plane`` is the mass's axial position along the rotor (any origin);
    ``name`` letters it on the polygons (``m1r1``); unnamed masses are
    numbered in order by :class:`BalancingSpec`.
    """

    mass: float
    radius: float
    angle_deg: float
    plane: float = 0.0
    name: str = ""

    def __post_init__(self) -> None:
        for argument in ("mass", "radius", "angle_deg", "plane"):
            object.__setattr__(self, argument, _finite(argument, getattr(self, argument)))
        if not self.mass > 0:
            raise ValueError(f"mass: must be > 0 (got {self.mass!r})")
        if not self.radius >= 0:
            raise ValueError(f"radius: must be >= 0 (got {self.radius!r})")
        if not isinstance(self.name, str):
            raise TypeError(f"name: must be a string (got {self.name!r})")

    @property
    def unbalance(self) -> complex:
        """The mass-radius product as a vector, m·r·e^{iθ} (kg·m)."""
        # Whole turns taken off in degrees, where fmod is exact: in radians a large angle keeps too few digits.
        return self.mass * self.radius * cmath.exp(1j * math.radians(math.fmod(self.angle_deg, 360.0)))

    @property
    def label(self) -> str:
        """The product's name on a polygon: ``m1r1``, ``mArA``; a long name as ``(m·r)name``."""
        return vector_name(self.name)


def vector_name(name: str) -> str:
    """The name of the mass-radius product of the mass (or plane) ``name``: ``m1r1``, ``mLrL``; a mass named
    as a mass is (``m1``, ``mA``) or as its product is (``m1r1``, the label the starter says an unnamed mass gets)
    gives its index alone, not ``mm1rm1`` nor ``(m·r)m1r1``."""
    index = symbol_index(name)
    if index is not None:
        name = index
    if len(name) <= 3 and name.isalnum():
        return f"m{name}r{name}"
    return f"(m·r){name}"


def symbol_index(name: str) -> str | None:
    """The index of a name written as a mass's symbol (``m1``, ``mA``) or its product's (``m1r1``, ``mArA``): an index
    as the polygons letter one, numbered up to three digits or one letter or digit; else None."""
    product = re.fullmatch(r"m(.+)r\1", name)
    index = product[1] if product else name[1:] if name[:1] == "m" else ""
    return index if (index.isdigit() and len(index) <= 3) or (len(index) == 1 and index.isalnum()) else None


def direction_deg(vector: complex) -> float:
    """The direction of a mass-radius product in [0, 360) degrees.  A phase a rounding below 0 (Σ m·r along +x of a
    mass at −180°, e^(−iπ) = −1 − 1.2e-16i) is 0, not the 360.0 that ``% 360`` makes of it."""
    angle = math.degrees(cmath.phase(vector)) % 360.0
    return 0.0 if angle >= 360.0 else angle


def default_plane_names(count: int) -> tuple[str, ...]:
    """The correction planes' names where the scene gives none: L and R of two, b of one."""
    return DYNAMIC_PLANE_NAMES if count == 2 else STATIC_PLANE_NAMES


def label_clash(names: Sequence[str], plane_names: Sequence[str]) -> tuple[str, int, int, str] | None:
    """The first two products that would read alike on the polygons and in the note (``m1r1`` of masses named
    ``1`` and ``m1``, a correction plane's ``mbrb`` and a mass ``b``'s), or None.

    ``("mass", k, j, label)``: mass k's label is mass j's (j < k); ``("plane", k, j, label)``: correction
    plane k's is mass j's.  ``names`` are the masses' as the polygons letter them (numbered where unnamed)."""
    # As they look: a Cyrillic А's mАrА is lettered as the Latin A's mArA.
    looks = [plain(vector_name(name)) for name in names]
    for k, label in enumerate(looks):
        if label in looks[:k]:
            return "mass", k, looks.index(label), vector_name(names[k])
    for k, plane in enumerate(plane_names):
        label = plain(vector_name(plane))
        if label in looks:
            return "plane", k, looks.index(label), vector_name(plane)
    return None


def _told_apart(name: str, other: str) -> str:
    """Which character is which, where two names that look alike are spelt apart ("; 'А' has the Cyrillic 'А'
    (U+0410) where 'A' has the Latin 'A' (U+0041)"); else ""."""
    return f"; {contrast(name, other)}" if name != other and plain(name) == plain(other) else ""


def _lookalike_in(names: Sequence[str]) -> tuple[int, int] | None:
    """The first name (k) of ``names`` that looks like an earlier one (j), spelt apart, as (k, j); or None."""
    for k, name in enumerate(names):
        other = twin(name, names[:k])
        if other is not None:
            return k, names.index(other)
    return None


@dataclass(frozen=True)
class BalancingSpec:
    """What to balance and where.

    Parameters
    ----------
    masses
        The rotating masses (at least one).
    planes
        The axial positions (m) of the correction planes: two for dynamic
        balancing; one for static balancing in that plane; none for static
        balancing of a disc, corrected in the masses' own plane (they must
        then share one plane).
    correction_radius
        The radius (m) at which each correction mass is fixed: one number for
        every plane, or one per plane; ``None`` gives the products m·r only.
    plane_names
        The planes' names (default ``L``, ``R``; ``b`` for one plane).
    """

    masses: Sequence[RotatingMass]
    planes: Sequence[float] = ()
    correction_radius: float | Sequence[float] | None = None
    plane_names: Sequence[str] = ()

    def __post_init__(self) -> None:
        masses = tuple(self.masses)
        if not masses:
            raise ValueError("masses: must hold at least one rotating mass")
        masses = tuple(mass if mass.name else replace(mass, name=str(k + 1)) for k, mass in enumerate(masses))
        names = [mass.name for mass in masses]
        for k, name in enumerate(names):
            if name in names[:k]:
                raise ValueError(f"masses[{k}].name: repeats the name of an earlier mass ({name!r})")
        if (alike := _lookalike_in(names)) is not None:
            k, j = alike
            raise ValueError(f"masses[{k}].name: looks the same as the name of an earlier mass ({names[j]!r}); "
                             f"{contrast(names[k], names[j])}: name the two apart")
        object.__setattr__(self, "masses", masses)
        planes = tuple(_finite(f"planes[{k}]", z) for k, z in enumerate(self.planes))
        if len(planes) > 2:
            raise ValueError(f"planes: must hold one or two correction planes (got {len(planes)})")
        if len(planes) == 2 and planes[0] == planes[1]:
            raise ValueError(f"planes: the two correction planes must differ (got {list(planes)})")
        if not planes and len({mass.plane for mass in masses}) > 1:
            raise ValueError("planes: masses in different planes need their correction planes: "
                             "two for dynamic balancing, or one to balance the force only")
        object.__setattr__(self, "planes", planes)
        count = max(1, len(planes))
        radius = self.correction_radius
        if radius is not None:
            radii = (radius,) * count if isinstance(radius, numbers.Real) else tuple(radius)
            if len(radii) != count:
                raise ValueError(f"correction_radius: must be one number or one per correction plane ({count})")
            for k, value in enumerate(radii):
                if not _finite(f"correction_radius[{k}]", value) > 0:
                    raise ValueError(f"correction_radius[{k}]: must be > 0 (got {value!r})")
            object.__setattr__(self, "correction_radius", tuple(float(value) for value in radii))
        plane_names = tuple(self.plane_names) or default_plane_names(count)
        if (len(plane_names) != count or len(set(plane_names)) != count
                or not all(isinstance(n, str) and n for n in plane_names)):
            raise ValueError(f"plane_names: must be {count} different names, one per correction plane")
        if (alike := _lookalike_in(plane_names)) is not None:
            k, j = alike
            raise ValueError(f"plane_names: {plane_names[k]!r} looks the same as {plane_names[j]!r}; "
                             f"{contrast(plane_names[k], plane_names[j])}: name the two apart")
        clash = label_clash(names, plane_names)
        if clash is not None:
            kind, k, j, label = clash
            if kind == "mass":
                where, told = f"masses[{k}].name", f"mass {names[k]!r} and mass {names[j]!r}"
                apart = _told_apart(names[k], names[j])
            else:
                where = "plane_names" if self.plane_names else f"masses[{j}].name"
                told = f"correction plane {plane_names[k]!r} and mass {names[j]!r}"
                apart = _told_apart(plane_names[k], names[j])
            raise ValueError(f"{where}: the products of {told} would both read {label}{apart}; give names whose "
                             "products read apart")
        object.__setattr__(self, "plane_names", plane_names)

    @property
    def dynamic(self) -> bool:
        """Whether the rotor is balanced in two planes (force and moment), not one (force only)."""
        return len(self.planes) == 2

    @property
    def correction_planes(self) -> tuple[float, ...]:
        """The axial positions (m) of the correction planes; for a disc, the masses' own plane."""
        return tuple(self.planes) or (self.masses[0].plane,)


@dataclass(frozen=True)
class PolygonVector:
    """One side of a plane's polygon: a mass-radius product laid off from ``start`` to ``end`` (kg·m).

    ``role`` is ``mass`` for a mass's share in the plane and ``correction``
    for the closing vector; ``name`` is its label (``m2r2``, ``mLrL``).
    """

    name: str
    start: complex
    end: complex
    role: str

    @property
    def vector(self) -> complex:
        return self.end - self.start


@dataclass(frozen=True)
class CorrectionPlane:
    """A correction plane and its polygon: the masses' shares head to tail, closed by the correction.

    ``factors`` are the shares of each mass's m·r carried to this plane
    (1 in static balancing; (zR − zi)/(zR − zL) in plane L), ``vectors`` the
    polygon in the order it is laid off, ``correction`` the closing vector
    mb·rb (kg·m), ``radius`` the correction mass's radius (m) when known.
    """

    name: str
    position: float
    factors: tuple[float, ...]
    vectors: tuple[PolygonVector, ...]
    correction: complex
    radius: float | None
    equation: str

    @property
    def shares(self) -> tuple[complex, ...]:
        """The masses' mass-radius products carried to this plane (kg·m), in the masses' order."""
        return tuple(vector.vector for vector in self.vectors if vector.role == "mass")

    @property
    def vertices(self) -> tuple[complex, ...]:
        """The polygon's corners (kg·m): its start, the end of each vector; the last is the start again."""
        return (self.vectors[0].start, *(vector.end for vector in self.vectors))

    @property
    def mass_radius(self) -> float:
        """|mb·rb| (kg·m), the correction's mass-radius product; 0 where the plane needs none, not the rounding left
        where the shares close by themselves (1e-16 kg·m), in the results, the drawing and the note alike."""
        return abs(self.correction) if self.needed else 0.0

    @property
    def needed(self) -> bool:
        """Whether the plane needs a correction: the masses' shares do not close by themselves (but for rounding,
        below :data:`NEGLIGIBLE` of the shares' Σ |(mi·ri)plane|, the masses' m·r carried to the plane)."""
        return abs(self.correction) > NEGLIGIBLE * sum(abs(share) for share in self.shares)

    @property
    def angle_deg(self) -> float | None:
        """The correction's angle in [0, 360) degrees; None where no correction is needed: a vector of no length has
        no direction, and 0° would read as a correction set along x."""
        if not self.needed:
            return None
        return direction_deg(self.correction)

    @property
    def mass(self) -> float | None:
        """The correction mass mb = |mb·rb| / rb (kg) at the given radius, or None without one."""
        return None if self.radius is None else self.mass_radius / self.radius


@dataclass(frozen=True)
class BalancingResult:
    """The balanced rotor: its correction planes, the unbalance before, the residual after.

    ``unbalance`` is Σ mi·ri of the masses (kg·m) and ``unbalance_moment``
    Σ mi·ri·zi about z = 0 (kg·m²), both as vectors in the rotor's frame;
    ``residual_force`` and ``residual_moment`` are the same sums with the
    corrections added, summed afresh from the masses and the corrections
    (times ω² they are the force and the moment on the bearings).
    """

    spec: BalancingSpec
    planes: tuple[CorrectionPlane, ...]
    unbalance: complex
    unbalance_moment: complex
    residual_force: complex
    residual_moment: complex

    @property
    def kind(self) -> str:
        return "dynamic" if self.spec.dynamic else "static"

    @property
    def residual(self) -> tuple[float, float]:
        """|Σ m·r| (kg·m) and |Σ m·r·z| (kg·m², about z = 0) of the corrected rotor, each written 0 where it is
        rounding (:meth:`_written`)."""
        return self._written(self.residual_force, self.residual_moment)

    @property
    def unbalance_written(self) -> tuple[float, float]:
        """|Σ m·r| (kg·m) and |Σ m·r·z| (kg·m², about z = 0) of the rotor before correction, rounding written 0."""
        return self._written(self.unbalance, self.unbalance_moment)

    def _written(self, force: complex, moment: complex) -> tuple[float, float]:
        """|force|, |moment|, each 0 below :data:`NEGLIGIBLE` of the rotor's own unbalance, Σ |mi·ri| (not of
        corrections that cancellation may have blown up); the moment's at the arm of the rotor's plane farthest
        from z = 0, masses' or corrections', the most a force left by rounding can have."""
        own = sum(abs(mass.unbalance) for mass in self.spec.masses)
        farthest = max(abs(z) for z in (*(mass.plane for mass in self.spec.masses), *self.spec.correction_planes))
        return _above_noise(abs(force), own), _above_noise(abs(moment), own * farthest)

    @property
    def balanced(self) -> bool:
        """Whether the corrections leave nothing but rounding: of the force, and in two planes of the moment too
        (one plane leaves the couple of masses in other planes, :func:`static_couple`)."""
        force, moment = self.residual
        return force == 0 and (moment == 0 or not self.spec.dynamic)


def balance(spec: BalancingSpec) -> BalancingResult:
    """The corrections that balance ``spec``'s masses, each found by closing its plane's polygon."""
    masses = spec.masses
    positions = spec.correction_planes
    if spec.dynamic:
        left, right = positions
        span = right - left
        factor_rows = [tuple((right - mass.plane) / span for mass in masses),
                       tuple((mass.plane - left) / span for mass in masses)]
    else:
        factor_rows = [tuple(1.0 for _ in masses)]
    radii = spec.correction_radius or (None,) * len(positions)
    planes = tuple(_close_polygon(name, position, factors, masses, radius, spec.dynamic)
                   for name, position, factors, radius in zip(spec.plane_names, positions, factor_rows, radii,
                                                              strict=True))
    unbalance = sum((mass.unbalance for mass in masses), 0j)
    moment = sum((mass.unbalance * mass.plane for mass in masses), 0j)
    return BalancingResult(
        spec=spec, planes=planes, unbalance=unbalance, unbalance_moment=moment,
        residual_force=unbalance + sum((plane.correction for plane in planes), 0j),
        residual_moment=moment + sum((plane.correction * plane.position for plane in planes), 0j))


def _close_polygon(name: str, position: float, factors: tuple[float, ...], masses: Sequence[RotatingMass],
                   radius: float | None, shared: bool) -> CorrectionPlane:
    """Σ (mi·ri)plane + mb·rb = 0: the shares head to tail from 0, the correction back to 0.

    Where the masses are ``shared`` between two planes, a side is a mass's share, not its m·r, and is named as
    one, ``(m1r1)L``: "m1r1 + m2r2 + mLrL = 0" would say what is false.  A mass turning in the other correction
    plane has no share in this one: its side is nothing, drawn nowhere, and the equation leaves it out as well."""
    vectors = []
    tip = 0j
    for mass, factor in zip(masses, factors, strict=True):
        share = mass.unbalance * factor
        vectors.append(PolygonVector(f"({mass.label}){name}" if shared else mass.label, tip, tip + share, "mass"))
        tip += share
    correction = PolygonVector(vector_name(name), tip, 0j, "correction")
    terms = [vector.name for vector, factor in zip(vectors, factors, strict=True) if factor != 0.0]
    equation = " + ".join([*terms, correction.name]) + " = 0"
    return CorrectionPlane(name=name, position=position, factors=factors, vectors=(*vectors, correction),
                           correction=-tip, radius=radius, equation=equation)


# --- the scene table -------------------------------------------------------------------------


# The symbols the textbooks give a rotating mass's keys by (lower case, as ``Table.named_otherwise`` compares them).
_MASS_SYMBOLS = (("radius", frozenset({"r", "ri"}), "a mass's radius"),
                 ("angle", frozenset({"theta", "θ", "phi", "φ", "alpha", "α"}), "a mass's angle"),
                 ("plane", frozenset({"z", "zi"}), "a mass's axial position"))


def read_balancing(table: Table) -> BalancingSpec:
    """The ``[balancing]`` table of a scene as a :class:`BalancingSpec`, each bad key named by its path.

    Keys: ``masses`` (a list of ``{mass, radius, angle, plane, name}``),
    ``planes`` (one or two axial positions, m), ``correction_radius`` (m, one
    number or one per plane), ``plane_names``.
    """
    planes = _planes(table)
    count = max(1, len(planes))
    pairs = table.items("masses")
    if not pairs:
        raise SceneError(table.where("masses"), "must list at least one rotating mass")
    masses = []
    names: dict[str, str] = {}
    named: list[str] = []
    for where, item in pairs:
        entry = Table(item, where)
        # A key written as the textbook's symbol is named with the one to write: "radius: is required but missing"
        # left the r typed for it unmentioned, and z was an unknown key with no word of plane.
        for key, symbols, what in _MASS_SYMBOLS:
            entry.named_otherwise(key, symbols, what)
        mass = entry.number("mass", positive=True)
        radius = entry.number("radius", non_negative=True)
        angle = entry.number("angle")
        plane = entry.number("plane", None)
        name = entry.string("name", None)
        entry.done()
        _refuse_written_as_nought(entry, mass, radius)
        if plane is None and len(planes) == 2:
            raise SceneError(entry.where("plane"), "is required when [balancing] has two correction planes "
                                                   "(the mass's axial position, m)")
        if name is not None:
            _refuse_long_name(entry.where("name"), name, "mass's", "its product m·r", "1, A, blade, impeller")
            if name in names:
                raise SceneError(entry.where("name"), f"repeats the name of {names[name]}", name)
            if (other := twin(name, names)) is not None:
                # Drawn alike, the polygons and the note would letter two products mArA, told apart by no one.
                raise SceneError(entry.where("name"), f"looks the same as the name of {names[other]} ({other!r}), "
                                 "and the polygons and the note would letter both alike; "
                                 f"{contrast(name, other)}: name the two apart", name)
            names[name] = where
        named.append(name or "")
        masses.append(RotatingMass(mass, radius, angle, 0.0 if plane is None else plane, name or ""))
    if not planes:
        given = {mass.plane for mass in masses}
        if len(given) > 1:
            raise SceneError(table.where("planes"), "is required when the masses lie in different planes: "
                                                    "[zL, zR] for dynamic balancing, or [z] to balance the force only")
    radius, radius_keys = _correction_radius(table, count)
    plane_names = _plane_names(table, count)
    table.done(elsewhere=keys_of_other_tables("balancing"))
    _refuse_label_clash(table, named, plane_names, count)
    spec = BalancingSpec(masses=tuple(masses), planes=planes, correction_radius=radius, plane_names=plane_names)
    result = balance(spec)
    _check_computable(result, table.where("planes"))
    _refuse_correction_beyond_rotor(result, radius_keys)
    return spec


def _refuse_long_name(where: str, name: str, whose: str, lettered: str, usual: str) -> None:
    """Refuse a name of more than :data:`LONGEST_NAME` characters, which the polygons letter ``lettered`` by."""
    if len(name) > LONGEST_NAME:
        raise SceneError(where, f"is {len(name)} characters long, and a {whose} name letters {lettered} on the "
                         f"polygons, beside sides drawn within {POLYGON_FIELD_MM:g} mm: give one of at most "
                         f"{LONGEST_NAME} characters ({usual})", name)


def _refuse_written_as_nought(entry: Table, mass: float, radius: float) -> None:
    """Refuse a mass, a radius off the axis or their product m·r of no more than the rounding noise: the note writes
    each as 0 (a mass of 1e-14 kg its m = 0 and m·r = 0 beside the others' products, as though it were not there), as
    no rotor's part is so light or so near its axis.  A radius of 0, a mass on the axis, is as typed."""
    if mass <= ROUNDING_NOISE:
        raise SceneError(entry.where("mass"), f"{written_as_nought('kg')}: no rotating mass is so light (the mass is "
                         "in kg; leave out a mass that is not there)", mass, hint="; a slip of the exponent?")
    if 0 < radius <= ROUNDING_NOISE:
        raise SceneError(entry.where("radius"), f"{written_as_nought('m')}; a mass on the axis has radius "
                         "= 0 (the radius is in m)", radius, hint="; a slip of the exponent?")
    if 0 < mass * radius <= ROUNDING_NOISE:
        product = f"its m·r = {mass:g}·{radius:g} = {mass * radius:.3g} kg·m"
        raise SceneError(entry.path, f"{written_as_nought('kg·m', product)}: no rotating mass unbalances a rotor so "
                         "little (m in kg, r in m); give its mass and radius, or radius = 0 for a mass on the axis",
                         hint="; a slip of the exponent?")


def _refuse_label_clash(table: Table, given: list[str], plane_names: tuple[str, ...], count: int) -> None:
    """Refuse names whose products would read alike ("mara + mbrb + mbrb = 0", or mass ``m1`` and mass ``1`` both
    ``m1r1``): the polygon and the note could not be told apart.  The key blamed is a name the scene gave: of two
    masses the later named one (an unnamed mass is numbered, ``2``), a mass's against a plane's default name
    (``b``; ``L``, ``R``), else ``plane_names``."""
    names = [name or str(k + 1) for k, name in enumerate(given)]
    planes = plane_names or default_plane_names(count)
    clash = label_clash(names, planes)
    if clash is None:
        return
    kind, k, j, label = clash

    def mass(index: int) -> str:
        told = f"named {given[index]!r}" if given[index] else f"unnamed, so numbered {names[index]}"
        return f"{table.where('masses')}[{index}] ({told})"

    if kind == "mass":
        blamed = k if given[k] else j
        other = j if blamed == k else k
        raise SceneError(join_path(join_path(table.where("masses"), blamed), "name"),
                         f"its product and that of {mass(other)} would both read {label} on the polygons and in the "
                         f"note{_told_apart(names[blamed], names[other])}; give names whose products read apart",
                         given[blamed])
    if plane_names or not given[j]:
        # A plane named as the mass is also gives its correction mass the mass's symbol: "mA = 1.204 kg" of mass A's 2.
        symbol = f" (and its correction mass m{planes[k]} the mass's symbol)" if planes[k] == names[j] else ""
        raise SceneError(table.where("plane_names"),
                         f"the product of correction plane {planes[k]!r} and that of {mass(j)} would both read {label} "
                         f"on the polygons and in the note{symbol}{_told_apart(planes[k], names[j])}; name the planes "
                         "apart from the masses",
                         list(planes))
    raise SceneError(join_path(join_path(table.where("masses"), j), "name"),
                     f"its product and that of correction plane {planes[k]!r} (the default name of "
                     f"{'the correction plane' if count == 1 else 'a correction plane'}) would both read {label} on "
                     f"the polygons and in the note{_told_apart(names[j], planes[k])}; give the mass another name, or "
                     "name the planes (plane_names)",
                     given[j])


def _check_computable(result: BalancingResult, where: str) -> None:
    """Refuse corrections that cannot be worked out to rounding: each mass's share in a plane grows as its distance
    over the planes' spacing, and where that ratio is vast the shares cancel to less than their own rounding."""
    if result.balanced or not result.spec.dynamic:
        return
    spec = result.spec
    left, right = spec.planes
    spacing = abs(right - left)
    distance = max(max(abs(mass.plane - left), abs(mass.plane - right)) for mass in spec.masses)
    raise SceneError(where, f"are {spacing:g} m apart, too close for a mass {distance:g} m from them "
                            f"({distance / spacing:.3g} times their spacing): the corrections cannot be worked out "
                            f"to rounding and would leave Σ m·r = {abs(result.residual_force):.3g} kg·m and "
                            f"Σ m·r·z = {abs(result.residual_moment):.3g} kg·m² of the rotor's unbalance; set the "
                            "planes farther apart", list(spec.planes))


def _planes(table: Table) -> tuple[float, ...]:
    pairs = table.items("planes", default=None)
    if pairs is None:
        return ()
    if len(pairs) not in (1, 2):
        raise SceneError(table.where("planes"), "must list one correction plane [z] or two [zL, zR] (m)",
                         table.data["planes"])
    planes = tuple(check_number(item, where) for where, item in pairs)
    if len(planes) == 2 and planes[0] == planes[1]:
        raise SceneError(table.where("planes"), "the two correction planes must be apart", list(planes))
    if len(planes) == 2 and planes[0] > planes[1] and not table.has("plane_names"):
        # Taken as given, the plane lettered L stood to the right of R, the polygons and the note naming them so.
        raise SceneError(table.where("planes"), f"must list the left plane L first, then the right R, along z: write "
                         f"[{planes[1]!r}, {planes[0]!r}], or name the planes as you list them (plane_names)",
                         list(planes))
    return planes


def _rotor_holding(spec: BalancingSpec, radii: Sequence[float]) -> tuple[float, float, float]:
    """The size a rotor is weighed at whose corrections turn at ``radii``: how far out its masses and corrections
    turn, R, and the radius it is weighed at (R, or, where R does not hold its masses, the least that does), m; and
    their span along the axis, m (:func:`_refuse_correction_beyond_rotor`)."""
    along = [mass.plane for mass in spec.masses] + list(spec.planes)
    span = max(along) - min(along)
    turning = max([mass.radius for mass in spec.masses] + list(radii))
    masses = sum(mass.mass for mass in spec.masses)
    return turning, solid_steel_reach(masses, span) if masses > heaviest_rotor(turning, span) else turning, span


def _holds(spec: BalancingSpec, radii: Sequence[float], keys: tuple[str, ...], k: int, radius: float,
           mass_radius: float) -> bool:
    """Whether plane ``k``'s correction of |m·r| ``mass_radius`` is within the rotor at ``radius`` given at its key
    (every plane that key sets turned at it)."""
    given = [radius if key == keys[k] else other for key, other in zip(keys, radii, strict=True)]
    _, weighed, span = _rotor_holding(spec, given)
    return mass_radius / radius <= heaviest_rotor(weighed, span)


def _refuse_correction_beyond_rotor(result: BalancingResult, keys: tuple[str, ...]) -> None:
    """Refuse a correction radius so small that the correction mass mb = |mb·rb|/rb outweighs any rotor of the
    scene's size (``correction_radius = 1e-9`` put 1.4e9 kg in a plane of the rotor starter's 42 kg of masses): at
    its key, with the correction mass and the least radius that keeps it within such a rotor.

    The bound is :func:`~graphplan.rotor_lengths.heaviest_rotor`, as for the masses' own (:func:`masses_in_grams`): a
    correction is fixed on the rotor, near its rim, so the rotor reaches at least as far out as the corrections and
    the masses turn, R, over the masses' and planes' span, and no rotor that size, solid steel twice as large in
    radius and length, weighs more; a correction heavier than that is no part of it.  Where the masses outweigh it
    themselves, R is not yet the rotor's size: the radii are eccentricities (a rotor of one mass is often a heavy
    disc 2 mm off its axis, which a correction radius of 1e-9 m gave a correction of 1e9 kg; not warned of, as
    :func:`~graphplan.rotor_lengths.radii_are_eccentricities` tells them) or the masses are in grams (warned of; their
    corrections follow them).  A rotor that holds them reaches at least as far as solid steel
    weighing them does (:func:`~graphplan.rotor_lengths.solid_steel_reach`), and is weighed at that size as any
    other: its corrections may weigh up to ROTOR_REACH³ times its masses.  The least radius told is one the check
    takes, found with the rotor's size at that radius."""
    spec = result.spec
    if not keys:
        return
    radii = [plane.radius or 0.0 for plane in result.planes]
    turning, radius, span = _rotor_holding(spec, radii)
    heaviest = heaviest_rotor(radius, span)
    k = max(range(len(result.planes)), key=lambda index: result.planes[index].mass or 0.0)
    plane = result.planes[k]
    if not (plane.mass or 0.0) > heaviest:
        return
    cylinder_radius, cylinder_length = bounding_cylinder(radius, span)
    steel = (f"solid steel filling a cylinder {cylinder_radius:.3g} m in radius and {cylinder_length:.3g} m long, "
             f"{heaviest:.4g} kg")
    if radius == turning:
        rotor = (f"any rotor whose masses and corrections turn within {radius:g} m of its axis over {span:g} m along "
                 f"it ({steel})")
    else:
        rotor = (f"any rotor that holds its masses, {sum(mass.mass for mass in spec.masses):g} kg together, turning "
                 f"within {turning:g} m of its axis: as solid steel they reach {radius:.3g} m from it over "
                 f"{rotor_length(radius, span):.3g} m along it, and no rotor that size outweighs {steel}")
    least = rounded_up(plane.mass_radius / heaviest)
    if not _holds(spec, radii, keys, k, least, plane.mass_radius):
        # At a larger radius the radii may hold the masses, and the rotor is weighed at that radius (a two-plane
        # rotor whose masses lie far beyond its planes loads one with shares of m·r many times their own): beyond
        # it a larger radius only lightens the correction and raises the bound, so the least is found by halving.
        low, high = least, 2 * least
        while not _holds(spec, radii, keys, k, high, plane.mass_radius):
            low, high = high, 2 * high
        for _ in range(60):
            middle = (low + high) / 2
            low, high = (low, middle) if _holds(spec, radii, keys, k, middle, plane.mass_radius) else (middle, high)
        least = rounded_up(high)
    raise SceneError(keys[k], f"puts a correction mass of {plane.mass:.4g} kg in plane {plane.name}, its |m·r| of "
                     f"{plane.mass_radius:.4g} kg·m over {plane.radius:g} m: heavier than {rotor}; a correction goes "
                     f"near the rim: give a correction radius of at least {least:g} m", plane.radius)


def _correction_radius(table: Table, count: int) -> tuple[tuple[float, ...] | None, tuple[str, ...]]:
    """The correction radii, one per plane, and the key each was given at (one for all where one number is
    given); None and no keys without a correction radius."""
    value = table.raw("correction_radius", None)
    where = table.where("correction_radius")
    if value is None:
        return None, ()
    if isinstance(value, list):
        if len(value) != count:
            raise SceneError(where, f"must be one radius or one per correction plane ({count})", value)
        radii = tuple(check_number(item, join_path(where, k)) for k, item in enumerate(value))
        wheres = [join_path(where, k) for k in range(count)]
    else:
        radii = (check_number(value, where),) * count
        wheres = [where] * count
    for at, radius in zip(wheres, radii, strict=True):
        if not radius > 0:
            raise SceneError(at, "must be > 0", radius)
        if radius <= ROUNDING_NOISE:
            raise SceneError(at, f"{written_as_nought('m')} (the radius is in m)", radius,
                             hint="; a slip of the exponent?")
    return radii, tuple(wheres)


def _plane_names(table: Table, count: int) -> tuple[str, ...]:
    pairs = table.items("plane_names", length=count, default=None)
    if pairs is None:
        return ()
    names = tuple(check_str(item, where) for where, item in pairs)
    for (where, _), name in zip(pairs, names, strict=True):
        _refuse_long_name(where, name, "plane's", "its correction's product and the shares carried to it",
                          "L, R, left, drive end")
        if (index := symbol_index(name)) is not None:
            # Taken as the index it stands for, the plane's correction would still be lettered by the name whole.
            raise SceneError(where, f"is written as a correction's symbol, and a plane's name is the index its "
                             f"correction is lettered by (mL, rL, θL, mLrL): {name!r} would letter its correction mass "
                             f"m{name}; name the plane {index!r}", name)
    if len(set(names)) != len(names):
        raise SceneError(table.where("plane_names"), "must be different names", list(names))
    if (alike := _lookalike_in(names)) is not None:
        k, j = alike
        raise SceneError(table.where("plane_names"), f"{names[k]!r} looks the same as {names[j]!r}, and the "
                         f"polygons and the note would letter both alike; {contrast(names[k], names[j])}: name the "
                         "two apart", list(names))
    return names


# --- results ---------------------------------------------------------------------------------


def balancing_results(result: BalancingResult) -> dict[str, Any]:
    """The balancing as the results file writes it: SI, angles in degrees.

    ``planes`` lists each correction plane with ``plane`` (its name),
    ``position`` (m), ``mass_radius`` (kg·m) and ``angle_deg`` (None where
    the plane needs no correction), and with
    ``radius`` (m) and ``mass`` (kg) when the correction radius is given;
    ``unbalance`` is the rotor's before correction, ``residual`` after; ``warnings`` lists each
    :func:`cautions` as ``{code, detail}``.
    """
    planes = []
    for plane in result.planes:
        entry: dict[str, Any] = {"plane": plane.name, "position": plane.position,
                                 "mass_radius": plane.mass_radius, "angle_deg": plane.angle_deg}
        if plane.radius is not None:
            entry["radius"] = plane.radius
            entry["mass"] = plane.mass
        planes.append(entry)
    force, moment = result.unbalance_written
    return {
        "kind": result.kind,
        # A rotor balanced already has no unbalance to point anywhere: its angle is null, as a zero correction's.
        "unbalance": {"mass_radius": force, "angle_deg": direction_deg(result.unbalance) if force else None,
                      "moment": moment},
        "planes": planes,
        # Zero but for rounding where the corrections balance: written as 0 below 1e-12 of the rotor's own
        # unbalance (not of the corrections, which cancellation may have blown up), as results.json writes every
        # quantity's rounding.
        "residual": dict(zip(("force", "moment"), result.residual, strict=True)),
        # Recorded beside the numbers they qualify: the command line's warning is gone once the run is over.
        "warnings": [{"code": found.code, "detail": found.detail} for found in cautions(result)],
    }


def static_couple(result: BalancingResult) -> float | None:
    """The couple (kg·m²) one correction plane leaves of masses turning in other planes, or None where it leaves
    none (a disc, its correction in its own plane) or the balancing is dynamic."""
    if result.spec.dynamic:
        return None
    scale = sum(abs(mass.unbalance) * (abs(mass.plane) + 1.0) for mass in result.spec.masses)
    couple = abs(result.residual_moment)
    return couple if couple > NEGLIGIBLE * scale else None


@dataclass(frozen=True)
class CoupleLeft:
    """One correction plane balances the force of masses turning in other planes but leaves their ``couple``
    Σ m·r·z (kg·m²), :func:`static_couple`."""

    couple: float
    code = "couple-left"

    @property
    def detail(self) -> str:
        """The warning in a line (English, as the command line prints it)."""
        return (f"one correction plane leaves the rotor a couple Σ m·r·z = {self.couple:.4g} kg·m² (its masses turn "
                "in other planes than the correction's); planes = [zL, zR] balances it dynamically")


@dataclass(frozen=True)
class PlanesClose:
    """Two correction planes so close for the masses' spread that the ``corrections``' Σ |mb·rb| (kg·m) is more than
    :data:`LARGE_CORRECTIONS` times the ``masses``' Σ |mi·ri|: the planes are ``spacing`` (m) apart, the farthest
    mass ``distance`` (m) from one of them."""

    corrections: float
    masses: float
    spacing: float
    distance: float
    code = "planes-close"

    @property
    def ratio(self) -> float:
        return self.corrections / self.masses

    @property
    def detail(self) -> str:
        """The warning in a line (English, as the command line prints it)."""
        return (f"the corrections' Σ |m·r| = {self.corrections:.4g} kg·m is {self.ratio:.3g} times the masses' "
                f"({self.masses:.4g} kg·m): the correction planes, {self.spacing:g} m apart, are close for masses up "
                f"to {self.distance:g} m from them, and the corrections make a large couple on a short arm; set the "
                "planes farther apart")


def planes_close(result: BalancingResult) -> PlanesClose | None:
    """Two correction planes whose corrections are more than :data:`LARGE_CORRECTIONS` times the masses' Σ |m·r|;
    else None (one plane's correction is never more than the masses')."""
    spec = result.spec
    if not spec.dynamic:
        return None
    own = sum(abs(mass.unbalance) for mass in spec.masses)
    corrections = sum(plane.mass_radius for plane in result.planes)
    if not corrections > LARGE_CORRECTIONS * own:
        return None
    left, right = spec.planes
    distance = max(max(abs(mass.plane - left), abs(mass.plane - right)) for mass in spec.masses)
    return PlanesClose(corrections=corrections, masses=own, spacing=abs(right - left), distance=distance)


@dataclass(frozen=True)
class OnAxis:
    """Every mass of the rotor turns on its axis (r = 0): it is balanced as it stands, which a rotor given to be
    balanced most likely is not (a radius left at 0)."""

    code = "on-axis"

    @property
    def detail(self) -> str:
        """The warning in a line (English, as the command line prints it)."""
        return ("every mass turns on the axis (radius = 0): the rotor is balanced as it stands, and no correction "
                "is needed; was a radius left at 0?")


def on_axis(spec: BalancingSpec) -> OnAxis | None:
    """:class:`OnAxis` where every mass's radius is 0; else None."""
    return OnAxis() if all(mass.radius == 0 for mass in spec.masses) else None


@dataclass(frozen=True)
class AnglesInRadians:
    """Every mass's angle lies within a turn's radians, |θ| ≤ 2π, and one at least is no whole degree: ``angles``
    typed in radians (π/2 for 90°), which the scene reads as degrees and which then put every mass within some 6° of
    the line they are counted from."""

    angles: tuple[float, ...]
    code = "angles-in-radians"

    @property
    def detail(self) -> str:
        """The warning in a line (English, as the command line prints it)."""
        given = ", ".join(f"{angle:g}" for angle in self.angles)
        meant = ", ".join(f"{math.degrees(angle):.4g}" for angle in self.angles)
        return (f"every mass's angle lies within 2π = 6.283 ({given}), and not all are whole degrees: radians? The "
                f"scene's angles are in degrees: as radians these are {meant}° (multiply them by 180/π)")


def angles_in_radians(spec: BalancingSpec) -> AnglesInRadians | None:
    """:class:`AnglesInRadians` where two masses or more all turn within 2π of the line their angles are counted
    from and one is no whole degree; else None.  A rotor's masses drawn a degree or two apart, at fractions of a
    degree, are no textbook's and no balancing machine's."""
    angles = tuple(mass.angle_deg for mass in spec.masses)
    if len(angles) < 2 or not all(abs(angle) <= 2 * math.pi for angle in angles):
        return None
    if all(angle == round(angle) for angle in angles):
        return None
    return AnglesInRadians(angles)


def lengths_in_millimetres(spec: BalancingSpec) -> LengthsInMillimetres | None:
    """The rotor's lengths that no machine has as metres, each with its key (``balancing.masses[0].radius``), as
    lengths typed in millimetres make them; None where they are plausible.  A radius over
    :data:`~graphplan.rotor_lengths.LARGEST_RADIUS_M`, a mass :data:`~graphplan.rotor_lengths.MIXED_RATIO` times
    farther out than the nearest correction, planes farther apart than
    :data:`~graphplan.rotor_lengths.LONGEST_ROTOR_M`; with two planes, a mass turning
    :data:`~graphplan.rotor_lengths.FLATTEST_ROTOR` times farther out than the rotor is long; with one, whose masses
    lie in planes apart, :data:`~graphplan.rotor_lengths.THINNEST_DISC` times farther out than they lie apart."""
    found = []
    for k, mass in enumerate(spec.masses):
        if mass.radius > LARGEST_RADIUS_M:
            found.append(Implausible("radius", f"balancing.masses[{k}].radius", mass.radius, LARGEST_RADIUS_M,
                                     name=mass.name))
    radii = tuple(spec.correction_radius or ())
    # One radius for every plane is named by its key alone, as the scene most likely gave it.
    keys = ["balancing.correction_radius" if len(set(radii)) == 1 else f"balancing.correction_radius[{k}]"
            for k in range(len(radii))]
    for k, radius in enumerate(radii):
        if radius > LARGEST_RADIUS_M and keys[k] not in {item.key for item in found}:
            found.append(Implausible("correction_radius", keys[k], radius, LARGEST_RADIUS_M,
                                     name=spec.plane_names[k]))
    if radii and not found:
        k, mass = max(enumerate(spec.masses), key=lambda item: item[1].radius)
        j = min(range(len(radii)), key=lambda index: radii[index])
        if mass.radius > MIXED_RATIO * radii[j]:
            found.append(Implausible("mixed", f"balancing.masses[{k}].radius", mass.radius, MIXED_RATIO,
                                     name=mass.name, other_key=keys[j], other=radii[j],
                                     other_name=spec.plane_names[j]))
    along = [(f"balancing.masses[{k}].plane", mass.plane) for k, mass in enumerate(spec.masses)]
    along += [(f"balancing.planes[{k}]", z) for k, z in enumerate(spec.planes)]
    (low_key, low), (high_key, high) = min(along, key=lambda item: item[1]), max(along, key=lambda item: item[1])
    if high - low > LONGEST_ROTOR_M:
        found.append(Implausible("rotor_length", high_key, high, LONGEST_ROTOR_M, other_key=low_key, other=low))
    elif len(spec.planes) == 2 and not found:
        k, mass = max(enumerate(spec.masses), key=lambda item: item[1].radius)
        if mass.radius > FLATTEST_ROTOR * (high - low):
            found.append(Implausible("flat_rotor", f"balancing.masses[{k}].radius", mass.radius, FLATTEST_ROTOR,
                                     name=mass.name, other_key=f"{low_key} to {high_key}", other=high - low))
        elif radii and max(radii) > FLATTEST_ROTOR * (high - low):
            # The corrections are masses on the same long rotor: Khurmi's 100 mm typed as 100 among metres.
            j = max(range(len(radii)), key=lambda index: radii[index])
            found.append(Implausible("flat_rotor_correction", keys[j], radii[j], FLATTEST_ROTOR,
                                     name=spec.plane_names[j], other_key=f"{low_key} to {high_key}", other=high - low))
    elif len(spec.planes) == 1 and not found and high > low:
        k, mass = max(enumerate(spec.masses), key=lambda item: item[1].radius)
        if mass.radius > THINNEST_DISC * (high - low):
            found.append(Implausible("thin_disc", f"balancing.masses[{k}].radius", mass.radius, THINNEST_DISC,
                                     name=mass.name, other_key=f"{low_key} to {high_key}", other=high - low))
    return LengthsInMillimetres(tuple(found)) if found else None


@dataclass(frozen=True)
class MassesInGrams:
    """The rotor's masses weigh together more than solid steel filling a cylinder twice as large in radius as the
    farthest out a mass or a correction turns and twice as long as its masses and planes span along the axis
    (:func:`~graphplan.rotor_lengths.heaviest_rotor`), as masses typed in grams make them: 200 for 0.2 kg on a rotor
    0.1 m across; read as grams, they lie within the radii they turn at
    (:func:`~graphplan.rotor_lengths.radii_are_eccentricities`).

    ``radius`` is that radius and ``radius_key`` where it is given (the span, where no correction radius gives the rim
    and the masses' radii are shorter); ``span`` the masses' and planes' span along the axis.
    """

    masses: tuple[float, ...]
    radius: float
    radius_key: str
    span: float
    code = "masses-in-grams"

    @property
    def length(self) -> float:
        """The rotor's length the cylinder is twice as long as: its span, or a disc's radius where that is longer, m."""
        return rotor_length(self.radius, self.span)

    @property
    def cylinder(self) -> tuple[float, float]:
        """The steel cylinder's radius and length, m (:func:`~graphplan.rotor_lengths.bounding_cylinder`)."""
        return bounding_cylinder(self.radius, self.span)

    @property
    def limit(self) -> float:
        """The most the masses of a rotor of this size weigh together, kg."""
        return heaviest_rotor(self.radius, self.span)

    @property
    def detail(self) -> str:
        """The warning in a line (English, as the command line prints it)."""
        k = max(range(len(self.masses)), key=lambda index: self.masses[index])
        heaviest = self.masses[k]
        along = ("the masses' and planes' span along the axis" if self.span >= self.radius
                 else f"its radius: its masses and planes lie {self.span:g} m apart along the axis, within a disc's "
                      "thickness")
        return (f"balancing.masses[{k}].mass = {heaviest:g} kg, the masses {sum(self.masses):.4g} kg together, on a "
                f"rotor {self.radius:g} m in radius ({self.radius_key}) and {self.length:g} m long ({along}): heavier "
                f"than solid steel filling a cylinder twice that in radius and in length ({self.limit:.3g} kg): grams "
                f"typed for kg? {heaviest:g} g is balancing.masses[{k}].mass = {heaviest / 1000:g}; the scene's masses "
                "are in kg (divide grams by 1000)")


def masses_in_grams(spec: BalancingSpec) -> MassesInGrams | None:
    """:class:`MassesInGrams` where two masses or more weigh together more than
    :func:`~graphplan.rotor_lengths.heaviest_rotor` of the rotor's radius (the farthest out a mass or a correction
    turns) and its masses' and planes' span along the axis, but typed in grams would lie within the radii they turn at;
    else None.  Masses that even as grams would not are bodies round the axis, their radii eccentricities
    (:func:`~graphplan.rotor_lengths.radii_are_eccentricities`: 500 kg discs 2 mm off their centres), and the scene
    gives no radius of the rotor: their own is not in it, and a correction radius beside them may be a collar's on the
    shaft.  One mass alone is not judged: its radius may be a heavy disc's eccentricity, and nothing else gives the
    rotor's size; nor, without a correction radius, does the scene give the rim, which lumps may turn well inside:
    the rotor's radius is then taken as at least its span."""
    if len(spec.masses) < 2:
        return None
    radii = [(mass.radius, f"balancing.masses[{k}].radius") for k, mass in enumerate(spec.masses)]
    corrections = tuple(spec.correction_radius or ())
    radii += [(radius, "balancing.correction_radius" if len(set(corrections)) == 1
               else f"balancing.correction_radius[{k}]") for k, radius in enumerate(corrections)]
    along = [mass.plane for mass in spec.masses] + list(spec.planes)
    span = max(along) - min(along)
    radius, key = max(radii, key=lambda item: item[0])
    if not corrections and span > radius:
        radius, key = span, ("taken as its span: no correction_radius is given, and the masses may turn well inside "
                             "the rim")
    masses = tuple(mass.mass for mass in spec.masses)
    # A rotor of no size (every mass on its axis, in one plane) is told so (on_axis), not weighed.
    if not radius > 0 or not sum(masses) > heaviest_rotor(radius, span):
        return None
    # Grams explain masses too heavy for their radii only where, read as grams, they would lie within them: the
    # refusal of a correction radius too small weighs the others as kg, discs off their centres.
    if radii_are_eccentricities(sum(masses), span, max(mass.radius for mass in spec.masses)):
        return None
    return MassesInGrams(masses, radius, key, span)


def cautions(result: BalancingResult) -> list[AnglesInRadians | CoupleLeft | LengthsInMillimetres | MassesInGrams
                                              | OnAxis | PlanesClose]:
    """What the balanced rotor is left that a reader should not miss: lengths that look typed in millimetres, masses
    that look typed in grams, angles that look typed in radians, masses all on the axis, corrections dwarfing the
    masses, the couple of one plane."""
    couple = static_couple(result)
    return [found for found in (lengths_in_millimetres(result.spec), masses_in_grams(result.spec),
                                angles_in_radians(result.spec), on_axis(result.spec), planes_close(result),
                                None if couple is None else CoupleLeft(couple)) if found is not None]


def _above_noise(value: float, scale: float) -> float:
    return 0.0 if value <= NEGLIGIBLE * scale else value


__all__ = ["LARGE_CORRECTIONS", "AnglesInRadians", "BalancingResult", "BalancingSpec", "CorrectionPlane", "CoupleLeft",
           "MassesInGrams", "OnAxis", "PlanesClose", "PolygonVector", "RotatingMass", "angles_in_radians", "balance",
           "balancing_results", "cautions", "direction_deg", "label_clash", "lengths_in_millimetres",
           "masses_in_grams", "on_axis", "planes_close", "read_balancing", "static_couple", "vector_name"]
