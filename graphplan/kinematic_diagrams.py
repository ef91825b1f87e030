"""Kinematic diagrams of the output link: displacement, velocity and acceleration over the driver's run.

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
working sense.  A link that turns round (it never turns back, so it has no
extremes and no strokes) goes on past a whole turn: its angle turned,
unwrapped, grows by a turn over each turn it makes.  The driver is taken to
move uniformly at the scene's speed, so that its coordinate is a time axis
(``t = φ/|ω|``, or ``t = s/|v|`` for a slider); a scene's ε of the crank (s̈
of a slider) is left out of the acceleration so that both methods describe
the same motion.

A crank that turns round gives one cycle, closed: the last interval runs back
to the first position, and the chord across the end of the cycle gives the
acceleration there.  A rocking crank (``driver.swing``) and a slider
(``driver.travel``) give one run from end to end, open: the acceleration is
found at the positions between the ends only, as the chords of the velocity
diagram reach no further.

The chord method's values on a grid of step h agree with the exact ones to
O(h²): a chord's slope is the derivative at its mid-interval up to
``h²·s‴/24``; the chord of two such slopes is the second derivative at the
node between them up to ``h²·s⁗/12``.  The velocity is therefore compared at
the mid-intervals and the acceleration at the positions.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING

import numpy as np

from .errors import SceneError
from .kinematics import at, dot
from .mechanism import Mechanism
from .motion import Motion, solve
from .positions import PositionSet, working_speed
from .scales import fit_scale
from .scene import Scene

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
# The longest φ axis and the tallest field of diagrams drawn larger to fill a big sheet (mm): 1°/mm over a turn.
GREATEST_AXIS_MM = 360.0
GREATEST_FIELD_MM = 120.0


@dataclass(frozen=True)
class DiagramScales:
    """The scale factors of the diagrams, each in SI units per mm of paper.

    ``along`` is the scale of the common abscissa in the driver's coordinate:
    μφ (rad/mm) for a crank, μs of its travel (m/mm) for a slider; ``time``
    μt = ``along``/|driver speed| (s/mm) is the same abscissa read as time;
    ``displacement`` is μs (m/mm, or rad/mm for a turning link), a
    standard value; ``velocity`` μv = μs/(μt·H1) and ``acceleration``
    μa = μv/(μt·H2) follow from the pole distances ``velocity_pole`` H1 and
    ``acceleration_pole`` H2 (mm), whole millimetres chosen so that each
    curve fills its field.
    """

    along: float
    time: float
    displacement: float
    velocity: float
    acceleration: float
    velocity_pole: float
    acceleration_pole: float
    axis_mm: float


@dataclass(frozen=True)
class KinematicDiagrams:
    """Displacement, velocity and acceleration of the output link over the driver's run, two ways.

    The abscissae (``along``, ``nodes``, ``midpoints``) are the driver's
    coordinate travelled from the first position: the angle a crank has
    turned through (rad) or the distance a slider has moved (m), 0 to
    ``span``.  ``along`` with ``s``, ``v``, ``a`` is the dense analytic
    solution.  ``nodes`` are the scene's positions in the order the driver
    meets them, numbered by ``numbers``; over a ``cyclic`` crank's turn the
    first position is repeated at 2π to close the cycle (``numbers`` then has
    one more entry than the scene's count, the first number again).
    ``midpoints`` are the mid-intervals.  ``v_chord`` (at the midpoints) and
    ``a_chord`` (at :attr:`a_chord_nodes`) are the chord method's values;
    ``v_mid`` and ``a_nodes`` the analytic ones at the midpoints and at every
    node.  The differences are in per cent of ``v_peak`` and ``a_peak``, the
    largest magnitudes of the analytic curves over the run.

    Units: for a translating link m, m/s, m/s² (``point`` names the point
    whose travel is drawn); for a turning link rad, rad/s, rad/s².
    ``driver`` is the driver's kind, ``"crank"`` or ``"slider"``, and
    ``driver_speed`` its |ω| (rad/s) or |v| (m/s).  ``stroke_end`` is the
    angle where the working stroke ends, when the positions of a turning
    crank start at the extreme where it begins.
    """

    link: int
    translating: bool
    point: str | None
    driver: str
    cyclic: bool
    span: float
    driver_speed: float
    numbers: tuple[int, ...]
    along: np.ndarray
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
    # The driver's ε (a slider's s̈), which the uniformly moving driver of the diagrams leaves out.
    driver_rate: float = 0.0
    # Whether the working sense is clockwise or backward: the diagrams' positive is then results.json's negative.
    reversed: bool = False
    # (abscissa, velocity) of the output link read off the velocity plan of each position that has one.
    v_plans: tuple[tuple[float, float], ...] = ()

    @property
    def intervals(self) -> int:
        """The number of intervals between positions, each one chord of the displacement diagram."""
        return len(self.midpoints)

    @property
    def step(self) -> float:
        """The interval between positions in the driver's coordinate (rad or m)."""
        return self.span / self.intervals

    @property
    def a_chord_nodes(self) -> np.ndarray:
        """The nodes the chord method gives the acceleration at: all of a cycle's, the inner ones of a run."""
        return self.nodes if self.cyclic else self.nodes[1:-1]

    @property
    def a_at_chord_nodes(self) -> np.ndarray:
        """The analytic acceleration at :attr:`a_chord_nodes`."""
        return self.a_nodes if self.cyclic else self.a_nodes[1:-1]

    @property
    def v_difference(self) -> np.ndarray:
        """Chord method minus analytic at the midpoints, % of the peak velocity."""
        return 100.0 * (self.v_chord - self.v_mid) / self.v_peak

    @property
    def a_difference(self) -> np.ndarray:
        """Chord method minus analytic at :attr:`a_chord_nodes`, % of the peak acceleration."""
        return 100.0 * (self.a_chord - self.a_at_chord_nodes) / self.a_peak

    @property
    def largest_v_difference(self) -> float:
        return float(np.max(np.abs(self.v_difference)))

    @property
    def largest_a_difference(self) -> float:
        return float(np.max(np.abs(self.a_difference)))


def interval_count(cyclic: bool, count: int) -> int:
    """The intervals between ``count`` positions: as many over a closed cycle, one fewer over an open run."""
    return count if cyclic else count - 1


def unavailable(scene: Scene, analysis: Analysis | None = None) -> str | None:
    """Why the scene's kinematic diagrams cannot be drawn (of ``analysis``, where given), or None when they can."""
    if scene.positions.working is None:
        return "needs the output link: positions.working"
    if scene.driver is not None and interval_count(scene.driver.cyclic, scene.positions.count) < 3:
        return "needs at least 3 intervals between positions for the chord method"
    if analysis is not None and analysis.motion.singular:
        # The chord method runs through every position, and the velocities of a singular one are not determined.
        number = analysis.positions.numbers[min(analysis.motion.singular)]
        return f"needs every position regular: position {number} is singular"
    return None


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


def greatest_pole(axis_mm: float) -> float:
    """The longest pole distance (mm) of diagrams on a φ axis ``axis_mm`` long: :data:`GREATEST_POLE_MM`, and as
    much longer as the axis is longer than :data:`AXIS_MM` (a pole distance that fills a field grows as μt
    shrinks, with the axis, whatever the field's height)."""
    return float(max(GREATEST_POLE_MM, math.floor(GREATEST_POLE_MM * axis_mm / AXIS_MM)))


def pole_distance(span_mm: float, range_value: float, scale: float, time_scale: float,
                  greatest: float = GREATEST_POLE_MM) -> float:
    """The whole pole distance H (mm) at which the derivative's range fills ``span_mm``.

    The derivative is drawn at ``μ' = μ/(μt·H)``, so its range takes
    ``range·μt·H/μ`` mm; H is rounded down to whole mm and kept between
    :data:`LEAST_POLE_MM` and ``greatest``.
    """
    if range_value <= 0:
        return greatest
    fitting = math.floor(span_mm * scale / (time_scale * range_value))
    return float(min(greatest, max(LEAST_POLE_MM, fitting)))


def kinematic_diagrams(mechanism: Mechanism, positions: PositionSet, samples: int = DENSE_SAMPLES,
                       axis_mm: float = AXIS_MM, field_mm: float = FIELD_MM,
                       greatest_pole_mm: float | None = None) -> KinematicDiagrams:
    """The kinematic diagrams of the output link (``[positions] working.link``) over the driver's run.

    The run is a crank's turn, or once over a rocking crank's swing or a
    slider's travel in the direction the driver moves.  ``samples`` analytic
    values over the run draw the exact curves; the chord method reads only
    the displacements at the scene's ``count`` positions.  The pole
    distances stop at ``greatest_pole_mm`` (:func:`greatest_pole` of the
    axis when not given), longer for a sheet with the room for them.
    """
    scene = mechanism.scene
    working = scene.positions.working
    if working is None:
        raise SceneError("positions.working", "kinematic diagrams need the output link: "
                         "name it as working = { link = N, sense = ... }")
    if samples < 4:
        raise ValueError(f"samples must be at least 4 (got {samples})")
    if not axis_mm > 0 or not field_mm > 0:
        raise ValueError(f"axis_mm and field_mm must be > 0 (got {axis_mm}, {field_mm})")
    driver = mechanism.driver
    count = len(positions.values)
    intervals = interval_count(driver.cyclic, count)
    if intervals < 3:
        run = "turn" if driver.cyclic else driver.run_key
        raise SceneError("positions.count", f"the chord method needs at least 3 intervals between positions; "
                         f"{count} positions over the {run} make {intervals}", count)
    speed, rate = driver.coordinate_speed, driver.coordinate_acceleration
    numbers = tuple(int(n) for n in positions.numbers)
    if driver.cyclic:
        start, span = float(positions.values[0]), 2.0 * math.pi
        numbers += (numbers[0],)
    else:
        first, last = float(positions.values[0]), float(positions.values[-1])
        span = abs(last - first)
        # The driver meets the positions in the order it moves: a run given against its speed is met backwards.
        if (last - first) * driver.sense < 0:
            first, numbers = last, numbers[::-1]
        start = first
    step = span / intervals
    along = np.linspace(0.0, span, samples + 1)
    nodes = step * np.arange(intervals + 1)
    midpoints = step * (np.arange(intervals) + 0.5)
    travelled = np.concatenate((along, nodes, midpoints))
    motion = solve(mechanism, start + driver.sense * travelled, positions.reference)
    s_all = _displacement(mechanism, motion, travelled)
    v_all, output_rate = working_speed(motion)
    # A uniformly moving driver: the acceleration its ε (s̈) adds belongs to no single driver speed.
    a_all = output_rate - rate * v_all / speed
    dense, at_nodes = slice(0, samples + 1), slice(samples + 1, samples + 2 + intervals)
    at_midpoints = slice(samples + 2 + intervals, None)
    s, v, a = (np.array(values[dense]) for values in (s_all, v_all, a_all))
    s_nodes = np.array(s_all[at_nodes])
    dt = step / abs(speed)
    v_chord = chord_derivative(s_nodes, dt)
    a_chord = closed_chord_derivative(v_chord, dt) if driver.cyclic else chord_derivative(v_chord, dt)
    along_scale = span / axis_mm
    time_scale = along_scale / abs(speed)
    displacement_scale = fit_scale(_drawn_range(s), field_mm)
    greatest = greatest_pole(axis_mm) if greatest_pole_mm is None else greatest_pole_mm
    velocity_pole = pole_distance(field_mm, _drawn_range(v), displacement_scale, time_scale, greatest)
    velocity_scale = displacement_scale / (time_scale * velocity_pole)
    acceleration_pole = pole_distance(field_mm, _drawn_range(a), velocity_scale, time_scale, greatest)
    scales = DiagramScales(along=along_scale, time=time_scale, displacement=displacement_scale,
                           velocity=velocity_scale, acceleration=velocity_scale / (time_scale * acceleration_pole),
                           velocity_pole=velocity_pole, acceleration_pole=acceleration_pole, axis_mm=axis_mm)
    translating = working.link in mechanism.translating
    for kind, dense, chords, scale in (("velocity", v, v_chord, scales.velocity),
                                       ("acceleration", a, a_chord, scales.acceleration)):
        values = np.concatenate((dense, chords))
        if _drawn_range(values) / scale > OUT_OF_REACH * field_mm:
            peak_at = along[int(np.argmax(np.abs(dense)))]
            raise _out_of_reach(kind, working.link, translating, values, scale,
                                numbers[int(np.argmin(np.abs(nodes - peak_at)))])
    stroke_end = None
    if positions.extremes is not None and math.isclose(positions.extremes[0], start, abs_tol=1e-12):
        stroke_end = (driver.sense * (positions.extremes[1] - start)) % (2.0 * math.pi)
    return KinematicDiagrams(
        link=working.link, translating=translating,
        point=motion.links[working.link].origin if translating else None, driver=driver.kind,
        cyclic=driver.cyclic, span=span, driver_speed=abs(speed), numbers=numbers,
        along=along, s=s, v=v, a=a, nodes=nodes, s_nodes=s_nodes, v_nodes=np.array(v_all[at_nodes]),
        a_nodes=np.array(a_all[at_nodes]), midpoints=midpoints, v_mid=np.array(v_all[at_midpoints]),
        v_chord=v_chord, a_chord=a_chord, v_peak=_peak(v), a_peak=_peak(a), scales=scales, stroke_end=stroke_end,
        driver_rate=rate, reversed=working.sense in ("cw", "backward"))


def of_analysis(analysis: Analysis, axis_mm: float = AXIS_MM, field_mm: float = FIELD_MM,
                greatest_pole_mm: float | None = None) -> KinematicDiagrams:
    """:func:`kinematic_diagrams` of a run's mechanism and positions (``graphplan.analysis.Analysis``), with
    the output link's velocity read off the velocity plan of each position that has one (:attr:`v_plans`)."""
    record = kinematic_diagrams(analysis.mechanism, analysis.positions, axis_mm=axis_mm, field_mm=field_mm,
                                greatest_pole_mm=greatest_pole_mm)
    return replace(record, v_plans=_read_off_plans(analysis, record))


def _read_off_plans(analysis: Analysis, record: KinematicDiagrams) -> tuple[tuple[float, float], ...]:
    """(abscissa, velocity) of the output link at each position with a velocity plan, as the plan gives it:
    ω of the link from its plan, or its point's velocity along the link's direction
    (:attr:`~graphplan.analysis.Analysis.drawn_velocities`)."""
    working = analysis.scene.positions.working
    assert working is not None
    sign = 1.0 if working.sense in ("ccw", "forward") else -1.0
    link = analysis.motion.links[working.link]
    node_of: dict[int, float] = {}
    for number, node in zip(record.numbers, record.nodes.tolist(), strict=True):
        node_of.setdefault(number, node)  # a cycle's first position again at 2π stays at 0
    found = []
    for position in analysis.drawn_velocities:
        plan = position.velocity
        if record.translating:
            speed = float(dot(at(link.u, position.index), plan.value(link.origin)))
        else:
            speed = plan.rates[working.link]
        found.append((node_of[position.number], sign * speed))
    return tuple(found)


def _displacement(mechanism: Mechanism, motion: Motion, travelled: np.ndarray) -> np.ndarray:
    """The output link's travel from the first value of ``motion``, positive in the working sense; ``travelled``
    is how far the driver has gone at each value of ``motion`` (the first 0), in any order."""
    working = mechanism.scene.positions.working
    assert working is not None
    link = motion.links[working.link]
    sign = 1.0 if working.sense in ("ccw", "forward") else -1.0
    shape = motion.driver.shape
    if working.link in mechanism.translating:
        along = np.broadcast_to(dot(link.u, motion.points[link.origin].r), shape)
        return sign * (along - along[0]) + 0.0   # + 0.0: no −0 at the first position
    angle = np.broadcast_to(np.asarray(link.angle, dtype=float), shape)
    # Unwrapped in the order the driver meets the values: a link that turns round goes on past a whole turn
    # rather than jumping back by one, and a rocker's swing across ±180° from its first angle stays whole.
    order = np.argsort(travelled, kind="stable")
    turned = np.empty(len(angle))
    turned[order] = np.unwrap(angle[order] - angle[0])
    return sign * turned + 0.0


# A derivative's diagram this many times its field tall even at the shortest pole distance is out of reach of the
# pole method: one position near a toggle, where it runs off to thousands of times its size elsewhere.
OUT_OF_REACH = 10.0


def _out_of_reach(kind: str, link: int, translating: bool, values: np.ndarray, scale: float,
                  nearest: int) -> SceneError:
    """The refusal of a derivative's diagram :data:`OUT_OF_REACH` times its field tall, its peak near position
    ``nearest``."""
    tall = _drawn_range(values) / scale
    peak = float(values[np.argmax(np.abs(values))])
    unit = ("m/s" if translating else "rad/s") + ("²" if kind == "acceleration" else "")
    typical = float(np.median(np.abs(values)))
    return SceneError("positions", (
        f"the {kind} diagram of link {link} cannot be drawn: its {kind} reaches {peak:.6g} {unit} near position "
        f"{nearest}, {abs(peak) / typical:.0f} times its middling size, and even at the shortest pole distance, "
        f"{LEAST_POLE_MM:g} mm, its diagram would be {tall:.4g} mm tall. Keep the driver's run clear of the toggle "
        'there, or leave "diagrams" out of output.include'))


def _drawn_range(values: np.ndarray) -> float:
    """The height a curve takes in its diagram, whose abscissa is its zero: from the axis when it stays one side."""
    return float(max(values.max(), 0.0) - min(values.min(), 0.0))


def _peak(values: np.ndarray) -> float:
    """The largest magnitude of a curve, 1 for a curve that is zero throughout (no division by zero)."""
    peak = float(np.max(np.abs(values)))
    return peak if peak > 0 else 1.0
