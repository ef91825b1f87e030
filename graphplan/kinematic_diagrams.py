"""Kinematic diagrams of the output link: displacement, velocity and acceleration over one cycle.

The course project draws the output link's displacement against the crank
angle from the scene's positions, then differentiates it graphically by the
chord method: the chord between two successive ordinates is the mean
derivative over the interval, laid off at the mid-interval.  By the pole
method a ray through a pole P at distance H from the origin, parallel to the
chord, cuts off on the ordinate axis the derivative at the scale
``μv = μs/(μt·H)``.  Differentiating the velocity diagram the same way gives
the acceleration.  Here the same is done with numbers (the chord slope is
``np.diff(s)/Δt``, exactly what the pole construction draws), beside the
analytic values of :func:`graphplan.motion.solve`, so that the diagrams show
how far the graphical derivative strays from the exact one.

The output link is ``[positions] working.link``.  Its displacement is its
angle ψ (rad) for a turning link and its travel along its own direction (m)
for a translating one, counted from the first position and positive in the
working sense.  The crank is taken to turn uniformly at the scene's ω, so
that its angle is a time axis (``t = φ/|ω|``); a scene's ε of the crank is
left out of the acceleration so that both methods describe the same motion.

The chord method's values on a grid of step h agree with the exact ones to
O(h²): a chord's slope is the derivative at its mid-interval up to
``h²·s‴/24``; the chord of two such slopes is the second derivative at the
node between them up to ``h²·s⁗/12``.  The velocity is therefore compared at
the mid-intervals and the acceleration at the positions.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from .errors import SceneError
from .kinematics import dot
from .mechanism import Mechanism
from .motion import Motion, solve
from .positions import PositionSet, working_speed
from .scales import fit_scale

if TYPE_CHECKING:  # analysis comes later in the flow; only its type is named here
    from .analysis import Analysis

# Samples of the analytic curves over one cycle.
DENSE_SAMPLES = 360
# Length of the φ axis on the paper (mm): 20 mm per interval for the usual 12 positions.
AXIS_MM = 240.0
# Height the range of each curve is fitted into (mm).
FIELD_MM = 50.0
# Bounds of a pole distance: a shorter one draws steep, unreadable rays, a longer one a wide sheet.
LEAST_POLE_MM = 10.0
GREATEST_POLE_MM = 80.0


@dataclass(frozen=True)
class DiagramScales:
    """The scale factors of the diagrams, each in SI units per mm of paper.

    ``angle`` is μφ (rad/mm) and ``time`` μt = μφ/|ω| (s/mm) of the common
    abscissa; ``displacement`` is μs (m/mm, or rad/mm for a turning link), a
    standard value; ``velocity`` μv = μs/(μt·H1) and ``acceleration``
    μa = μv/(μt·H2) follow from the pole distances ``velocity_pole`` H1 and
    ``acceleration_pole`` H2 (mm), whole millimetres chosen so that each
    curve fills its field.
    """

    angle: float
    time: float
    displacement: float
    velocity: float
    acceleration: float
    velocity_pole: float
    acceleration_pole: float
    axis_mm: float


@dataclass(frozen=True)
class KinematicDiagrams:
    """Displacement, velocity and acceleration of the output link over one cycle, two ways.

    Angles of the crank (``phi``, ``nodes``, ``midpoints``) are the angles it
    has turned through from the first position, 0 to 2π.  ``phi`` with ``s``,
    ``v``, ``a`` is the dense analytic solution; ``nodes`` are the scene's
    positions with the first repeated at 2π to close the cycle (``numbers``
    has one more entry than the scene's count, the first number again);
    ``midpoints`` are the mid-intervals.  ``v_chord`` (at the midpoints) and
    ``a_chord`` (at the nodes) are the chord method's values; ``v_mid`` and
    ``a_nodes`` the analytic ones at the same angles.  The differences are in
    per cent of ``v_peak`` and ``a_peak``, the largest magnitudes of the
    analytic curves over the cycle.

    Units: for a translating link m, m/s, m/s² (``point`` names the point
    whose travel is drawn); for a turning link rad, rad/s, rad/s².
    ``stroke_end`` is the angle where the working stroke ends, when the
    positions start at the extreme where it begins.
    """

    link: int
    translating: bool
    point: str | None
    omega: float
    numbers: tuple[int, ...]
    phi: np.ndarray
    s: np.ndarray
    v: np.ndarray
    a: np.ndarray
    nodes: np.ndarray
    s_nodes: np.ndarray
    v_nodes: np.ndarray
    a_nodes: np.ndarray
    midpoints: np.ndarray
    v_mid: np.ndarray
    v_chord: np.ndarray
    a_chord: np.ndarray
    v_peak: float
    a_peak: float
    scales: DiagramScales
    stroke_end: float | None = None

    @property
    def count(self) -> int:
        """The number of positions in the cycle (intervals of the chord method)."""
        return len(self.midpoints)

    @property
    def step(self) -> float:
        """The interval Δφ between positions (rad)."""
        return 2.0 * math.pi / self.count

    @property
    def v_difference(self) -> np.ndarray:
        """Chord method minus analytic at the midpoints, % of the peak velocity."""
        return 100.0 * (self.v_chord - self.v_mid) / self.v_peak

    @property
    def a_difference(self) -> np.ndarray:
        """Chord method minus analytic at the positions, % of the peak acceleration."""
        return 100.0 * (self.a_chord - self.a_nodes) / self.a_peak

    @property
    def largest_v_difference(self) -> float:
        return float(np.max(np.abs(self.v_difference)))

    @property
    def largest_a_difference(self) -> float:
        return float(np.max(np.abs(self.a_difference)))


def chord_derivative(values: np.ndarray, step: float) -> np.ndarray:
    """The slopes of the chords between successive ordinates: the derivative at each mid-interval.

    This is what the pole construction draws: a ray from a pole at distance H
    parallel to the chord cuts the ordinate ``H·Δy/Δx`` on the axis.
    """
    if step <= 0:
        raise ValueError(f"the step of the chord method must be > 0 (got {step!r})")
    return np.diff(np.asarray(values, dtype=float)) / step


def closed_chord_derivative(values: np.ndarray, step: float) -> np.ndarray:
    """The chord method over a closed cycle: the ordinates at the mid-intervals, read as ``values`` at the nodes.

    ``values`` are the ordinates at mid-intervals ½, 3/2, … of a periodic
    curve; the chord from the last to the first (across the end of the
    cycle) gives the derivative at node 0.  The result has one value per node
    with node 0 repeated at the end, ``len(values) + 1`` in all.
    """
    values = np.asarray(values, dtype=float)
    around = chord_derivative(np.concatenate((values[-1:], values)), step)
    return np.append(around, around[0])


def pole_distance(span_mm: float, range_value: float, scale: float, time_scale: float) -> float:
    """The whole pole distance H (mm) at which the derivative's range fills ``span_mm``.

    The derivative is drawn at ``μ' = μ/(μt·H)``, so its range takes
    ``range·μt·H/μ`` mm; H is rounded down to whole mm and kept between
    :data:`LEAST_POLE_MM` and :data:`GREATEST_POLE_MM`.
    """
    if range_value <= 0:
        return GREATEST_POLE_MM
    fitting = math.floor(span_mm * scale / (time_scale * range_value))
    return float(min(GREATEST_POLE_MM, max(LEAST_POLE_MM, fitting)))


def kinematic_diagrams(mechanism: Mechanism, positions: PositionSet, samples: int = DENSE_SAMPLES,
                       axis_mm: float = AXIS_MM, field_mm: float = FIELD_MM) -> KinematicDiagrams:
    """The kinematic diagrams of the output link (``[positions] working.link``) over one crank turn.

    ``samples`` analytic values per cycle draw the exact curves; the chord
    method reads only the displacements at the scene's ``count`` positions.
    """
    scene = mechanism.scene
    working = scene.positions.working
    if working is None:
        raise SceneError("positions.working", "kinematic diagrams need the output link: "
                         "name it as working = { link = N, sense = ... }")
    driver = mechanism.driver
    if driver.kind != "crank":
        raise SceneError("driver.kind", "kinematic diagrams are drawn against a crank's angle; "
                         "a slider driver has none", driver.kind)
    if not driver.cyclic:
        raise SceneError("driver.swing", "kinematic diagrams are drawn over a crank's turn; "
                         "a rocking crank makes none", [round(math.degrees(end), 6) for end in driver.travel])
    if samples < 4:
        raise ValueError(f"samples must be at least 4 (got {samples})")
    if not axis_mm > 0 or not field_mm > 0:
        raise ValueError(f"axis_mm and field_mm must be > 0 (got {axis_mm}, {field_mm})")
    count = len(positions.values)
    if count < 3:
        raise SceneError("positions.count", "the chord method needs at least 3 positions", count)
    start = float(positions.values[0])
    omega, epsilon = float(driver.omega), float(driver.epsilon)
    speed = abs(omega)
    step = 2.0 * math.pi / count
    phi = np.linspace(0.0, 2.0 * math.pi, samples + 1)
    nodes = step * np.arange(count + 1)
    midpoints = step * (np.arange(count) + 0.5)
    turned = np.concatenate((phi, nodes, midpoints))
    motion = solve(mechanism, start + driver.sense * turned, positions.reference)
    s_all = _displacement(mechanism, motion)
    v_all, rate = working_speed(motion)
    # A uniformly turning crank: the ε·ds/dφ the scene's ε adds belongs to no single crank speed.
    a_all = rate - epsilon * v_all / omega
    dense, at_nodes = slice(0, samples + 1), slice(samples + 1, samples + 2 + count)
    at_midpoints = slice(samples + 2 + count, None)
    s, v, a = (np.array(values[dense]) for values in (s_all, v_all, a_all))
    s_nodes = np.array(s_all[at_nodes])
    dt = step / speed
    v_chord = chord_derivative(s_nodes, dt)
    a_chord = closed_chord_derivative(v_chord, dt)
    angle_scale = 2.0 * math.pi / axis_mm
    time_scale = angle_scale / speed
    displacement_scale = fit_scale(float(np.ptp(s)), field_mm)
    velocity_pole = pole_distance(field_mm, float(np.ptp(v)), displacement_scale, time_scale)
    velocity_scale = displacement_scale / (time_scale * velocity_pole)
    acceleration_pole = pole_distance(field_mm, float(np.ptp(a)), velocity_scale, time_scale)
    scales = DiagramScales(angle=angle_scale, time=time_scale, displacement=displacement_scale,
                           velocity=velocity_scale, acceleration=velocity_scale / (time_scale * acceleration_pole),
                           velocity_pole=velocity_pole, acceleration_pole=acceleration_pole, axis_mm=axis_mm)
    translating = working.link in mechanism.translating
    numbers = tuple(int(n) for n in positions.numbers) + (int(positions.numbers[0]),)
    stroke_end = None
    if positions.extremes is not None and math.isclose(positions.extremes[0], start, abs_tol=1e-12):
        stroke_end = (driver.sense * (positions.extremes[1] - start)) % (2.0 * math.pi)
    return KinematicDiagrams(
        link=working.link, translating=translating,
        point=motion.links[working.link].origin if translating else None, omega=omega, numbers=numbers,
        phi=phi, s=s, v=v, a=a, nodes=nodes, s_nodes=s_nodes, v_nodes=np.array(v_all[at_nodes]),
        a_nodes=np.array(a_all[at_nodes]), midpoints=midpoints, v_mid=np.array(v_all[at_midpoints]),
        v_chord=v_chord, a_chord=a_chord, v_peak=_peak(v), a_peak=_peak(a), scales=scales, stroke_end=stroke_end)


def of_analysis(analysis: Analysis) -> KinematicDiagrams:
    """:func:`kinematic_diagrams` of a run's mechanism and positions (``graphplan.analysis.Analysis``)."""
    return kinematic_diagrams(analysis.mechanism, analysis.positions)


def _displacement(mechanism: Mechanism, motion: Motion) -> np.ndarray:
    """The output link's travel from the first value of ``motion``, positive in the working sense."""
    working = mechanism.scene.positions.working
    assert working is not None
    link = motion.links[working.link]
    sign = 1.0 if working.sense in ("ccw", "forward") else -1.0
    shape = motion.driver.shape
    if working.link in mechanism.translating:
        along = np.broadcast_to(dot(link.u, motion.points[link.origin].r), shape)
        return sign * (along - along[0]) + 0.0   # + 0.0: no −0 at the first position
    angle = np.broadcast_to(np.asarray(link.angle, dtype=float), shape)
    # A rocker swings through less than a half turn: its angle wrapped about the first stays continuous.
    return sign * np.angle(np.exp(1j * (angle - angle[0]))) + 0.0


def _peak(values: np.ndarray) -> float:
    """The largest magnitude of a curve, 1 for a curve that is zero throughout (no division by zero)."""
    peak = float(np.max(np.abs(values)))
    return peak if peak > 0 else 1.0
