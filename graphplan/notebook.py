"""The Python interface for notebooks: a position's plans that show themselves as drawings.

::

    scene = graphplan.load("fixtures/ratchet_crank_rocker.toml")
    motion = scene.solve()            # the analytic solution at the scene's positions
    five = scene.plan(5)              # the plans of position 5; in Jupyter it shows its plan sheet
    five.values["VB"], five.velocity.scale, five.forces_drawing
    numbers = scene.results()         # results.json as a dict, nothing written
    scene.drawings()["diagrams.svg"]  # any SVG file of the run, by its name, nothing written
    rotor = graphplan.load("rotor.toml").balance()   # the correction planes; in Jupyter it shows its polygons
    rotor.planes[0].mass_radius, rotor.results["planes"], rotor.drawing.save("polygons.png")
    shaking = graphplan.load("rotor.toml").vibration_response()
    shaking.response.amplitude, shaking.results["transmissibility"], shaking.magnification_plot
"""

from __future__ import annotations

import copy
import dataclasses
import os
from dataclasses import dataclass
from functools import cached_property
from pathlib import Path
from types import MappingProxyType

import numpy as np

from .analysis import Analysis, PlanPosition, analyse, measured_on_velocity_plans
from .check import ErrorRow
from .errors import SceneError
from .forces import ForcePlan
from .lookalikes import NamedValues
from .memo import OwnedMemo
from .motion import solve
from .plans import Plan
from .report.plot_style import PLOT_DPI
from .rotor_balancing import BalancingResult, CorrectionPlane
from .scene import Scene, missing_part, not_a_scene
from .vibration import Response


@dataclass(frozen=True)
class Drawing:
    """An SVG drawing that Jupyter shows inline and that can be saved."""

    svg: str
    #: The PNG's resolution: the drawings' export's, or a plot's (plot_style.PLOT_DPI), as the command line writes.
    png_dpi: float | None = None

    def __repr__(self) -> str:
        # The whole SVG, some 25 000 characters, was its repr; Jupyter shows the drawing itself.
        return f"<Drawing: {len(self.svg)} characters of SVG>"

    def _repr_svg_(self) -> str:
        return self.svg

    def save(self, path: str | Path) -> Path:
        """Write the drawing to ``path`` as its suffix says: ``.svg`` (its size in mm, as printed), ``.png``
        (at the command line's resolution) or ``.pdf``; returns the path."""
        from .render.export import Rendering

        if not isinstance(path, str | os.PathLike):  # pathlib's error named neither save nor its path
            raise TypeError(f"save takes the path of the file to write, such as 'plan.svg' (got {path!r})")
        path = Path(path).expanduser()  # a notebook has no shell to expand ~
        if path.is_dir():  # told its name had no suffix, or, named plan.svg, IsADirectoryError from the write
            raise IsADirectoryError(f"{path}: is a folder; save the drawing as a file in it, such as "
                                    f"{path / 'drawing.svg'}")
        suffix = path.suffix.lower()
        if suffix == ".svg":
            path.write_text(self.svg, encoding="utf-8")
        elif suffix in (".png", ".pdf"):
            # Converted before the file is opened: a failed conversion leaves no empty file behind.
            path.write_bytes(Rendering(self.svg, suffix[1:], self.png_dpi).rendered())
        else:
            raise ValueError(f"a drawing is saved as .svg, .png or .pdf, as its name's suffix says (got {path.name!r})")
        return path


# The μl a scene's run draws at, by scene: choosing it lays every plan position's sheets out at a few μl (2 to 4 s on
# the shaper), and each plan(n) of one scene would choose the same again.
_RUN_LENGTH_SCALES: OwnedMemo[float] = OwnedMemo()


@dataclass(frozen=True)
class PositionPlans:
    """The plans of one position: the records, the values read off them, the drawings."""

    analysis: Analysis = dataclasses.field(repr=False)
    position: PlanPosition = dataclasses.field(repr=False)
    # The scene as given, whose run's μl the drawings take: ``analysis`` is of a copy that plans this position alone.
    scene: Scene = dataclasses.field(repr=False)

    def __repr__(self) -> str:
        # The dataclass's own repr printed the whole analysis (hundreds of thousands of characters).
        return f"<PositionPlans of position {self.number} of {self.analysis.scene.title!r}>"

    @property
    def number(self) -> int:
        """The position's number, as the scene numbers its positions."""
        return self.position.number

    @property
    def velocity(self) -> Plan:
        """The velocity plan: its scale (``scale``, m/s per mm), its vectors and the steps it was built in."""
        return self.position.velocity

    @property
    def acceleration(self) -> Plan:
        """The acceleration plan, as :attr:`velocity`."""
        return self.position.acceleration

    @property
    def values(self) -> NamedValues:
        """Every quantity read off the plans as constructed, SI, keyed as the error table names them: ``VB``,
        ``aB`` (magnitudes, m/s and m/s²), ``omega3``, ``epsilon4`` (rad/s and rad/s², signed, counter-clockwise
        positive), and the sliding pairs' relative velocity (``VA4A3``) and relative acceleration along the guide
        (``aA4A3^r``); ``aA4A3`` without ``^r`` is the whole of aA4 − aA3, the Coriolis term 2·ω4·VA4A3 in it."""
        return NamedValues({reading.quantity: reading.value(self.position.plans) for reading in self.position.readings},
                           "is no value of the plans, which give")

    @property
    def errors(self) -> tuple[ErrorRow, ...]:
        """The error table's rows: each quantity as constructed and as read off the plan against the exact one."""
        return self.position.errors

    @property
    def forces(self) -> ForcePlan | None:
        """The force analysis of the position (reactions as complex numbers x + iy, N; the balancing load), or
        None when the scene has no masses and no loads."""
        return self.position.forces

    @cached_property
    def _drawn(self) -> Analysis:
        """The analysis at the μl the scene's run draws its mechanism at.

        Left to the program, μl is the one that lays the run's drawings (every plan position's) on the fewest
        sheets: chosen for this position alone, it drew the mechanism at 0.005 m/mm where the run's plan sheet has
        0.004.  The run's analysis is worked out only here, when a drawing is asked for."""
        from .render.drawings import at_length_scale, length_scale

        if self.scene.drawing.length_scale is not None:
            return self.analysis
        chosen = _RUN_LENGTH_SCALES.get(self.scene, "run", lambda: length_scale(analyse(self.scene)))
        return at_length_scale(self.analysis, chosen)

    @cached_property
    def drawing(self) -> Drawing:
        """The plan sheet: the mechanism in the position (at the run's μl), its velocity and acceleration plans."""
        from .render.drawings import plan_svg

        return Drawing(plan_svg(self._drawn, self.position.index, self.position.velocity,
                                self.position.acceleration))

    @cached_property
    def velocity_drawing(self) -> Drawing:
        """The velocity plan alone, under its caption (μV): a report's figure, the plan sheet's without the
        mechanism and the acceleration plan."""
        from .render.drawings import plan_alone_svg

        return Drawing(plan_alone_svg(self._drawn, self.position, "velocity"))

    @cached_property
    def acceleration_drawing(self) -> Drawing:
        """The acceleration plan alone, under its caption (μa), as :attr:`velocity_drawing` is the velocity plan."""
        from .render.drawings import plan_alone_svg

        return Drawing(plan_alone_svg(self._drawn, self.position, "acceleration"))

    @cached_property
    def forces_drawing(self) -> Drawing | None:
        """The force sheet, or None when the scene has no masses and no loads."""
        if self.position.forces is None:
            return None
        from .render.drawings import forces_svg

        return Drawing(forces_svg(self._drawn, self.position))

    @cached_property
    def forces_with_friction_drawing(self) -> Drawing | None:
        """The force sheet with the pairs' friction, or None without ``[[friction]]`` or where the mechanism locks."""
        rubbing = self.position.with_friction
        if rubbing is None or rubbing.locked:
            return None
        from .render.drawings import forces_svg

        return Drawing(forces_svg(self._drawn, self.position, with_friction=True))

    def _repr_svg_(self) -> str:
        return self.drawing.svg


def warn_of(line: str) -> None:
    """``line``, one the command line prints after ``warning:`` (a machine that stalls, a stiffness typed in kN/m),
    warned of with a ``UserWarning`` at the notebook's line."""
    import warnings

    from . import _caller_level

    warnings.warn(line, UserWarning, stacklevel=_caller_level())


def warn_of_slips(analysis: Analysis) -> Analysis:
    """``analysis``, its warnings of the scene as a whole (a speed in rpm, lengths in mm, masses in grams) warned of
    with a ``UserWarning`` first: the command line prints them, and a notebook's numbers, off a thousandfold, came
    with no word."""
    from .analysis import SCENE_WIDE_WARNINGS

    for warning in analysis.warnings:
        if warning.code in SCENE_WIDE_WARNINGS:
            warn_of(f"{warning.code}: {warning.detail}")
    return analysis


def plan(scene: Scene, number: int) -> PositionPlans:
    """The plans of the position numbered ``number`` (as the scene numbers them), drawn whether listed or not."""
    if not isinstance(scene, Scene):  # a path failed on its missing .positions
        raise not_a_scene("plan", scene)
    if not scene.has_linkage:
        raise missing_part(scene, "mechanism")
    first = scene.positions.number_from
    if isinstance(number, bool) or not isinstance(number, int | np.integer):
        raise TypeError(f"a position is named by its number, an integer: plan(5), not plan({number!r})")
    number = int(number)
    if not first <= number < first + scene.positions.count:
        raise SceneError("positions", f"no position {number}: the scene numbers its positions {first} to "
                                      f"{first + scene.positions.count - 1}")
    # Hand readings of other positions belong to their own plans; those of a position the scene draws only among
    # the velocity plans of every position were read off that smaller plan, at its μV, not off this plan sheet's.
    hand = scene.measured.get(number)
    on_grid = number in scene.positions.velocity_plans and number not in scene.positions.plans
    measured = MappingProxyType({number: hand} if hand and not on_grid else {})
    only = dataclasses.replace(scene, positions=dataclasses.replace(scene.positions, plans=(number,)), measured=measured)
    analysis = analyse(only)
    if not analysis.plans:
        # A toggle the analytic solution meets is the Python interface's SingularPositionError, as solve() raises it.
        index = number - first
        solve(analysis.mechanism, analysis.positions.values[index:index + 1], analysis.positions.reference, [number])
        reason = next((warning.detail for warning in analysis.warnings
                       if int(analysis.positions.numbers[warning.position]) == number), "it is singular")
        raise SceneError("positions", f"position {number} has no plans: {reason}")
    warn_of_slips(analysis)
    position = analysis.plans[0]
    if hand and on_grid:
        position = dataclasses.replace(position, errors=position.errors + measured_on_velocity_plans(analysis, number,
                                                                                                      hand))
    return PositionPlans(analysis, position, scene)


@dataclass(frozen=True)
class RotorBalancing:
    """The rotor's balancing as a run works it out: each correction plane's polygon of mass-radius products closed
    by its correction, the numbers ``results.json`` writes and the polygons' drawing, which Jupyter shows."""

    scene: Scene = dataclasses.field(repr=False)

    def __repr__(self) -> str:
        # A zero correction has no angle (None): written —, as the drawing writes it.
        corrections = "; ".join(f"plane {plane.name}: {plane.mass_radius:.4g} kg·m at "
                                + ("—" if plane.angle_deg is None else f"{plane.angle_deg:.1f}°")
                                for plane in self.planes)
        return f"<RotorBalancing of {self.scene.title!r}: {corrections}>"

    @cached_property
    def result(self) -> BalancingResult:
        """The record the run works from: the planes, the rotor's unbalance before (``unbalance``, kg·m, and
        ``unbalance_moment``, kg·m²) and after (``residual``)."""
        from .rotor_balancing import balance

        assert self.scene.balancing is not None
        return balance(self.scene.balancing)

    @property
    def planes(self) -> tuple[CorrectionPlane, ...]:
        """Each correction plane: its ``name`` and ``position`` (m along the axis), its correction's
        ``mass_radius`` (kg·m) and ``angle_deg``, its ``mass`` (kg, None without a correction radius) and the
        polygon's ``vectors`` as laid off (kg·m, complex numbers x + iy)."""
        return self.result.planes

    @property
    def results(self) -> dict:
        """``results.json``'s ``balancing``, as the run writes it: ``kind``, ``planes``, ``unbalance``, ``residual``,
        ``warnings``; a copy of the script's own, which the next ask hands out as the run wrote it again."""
        return copy.deepcopy(self._document)

    @cached_property
    def _document(self) -> dict:
        from .deliverables import balancing_document

        return balancing_document(self.scene)

    @cached_property
    def drawing(self) -> Drawing:
        """The polygons of mass-radius products, one per correction plane: the run's ``rotor_balancing.svg``."""
        from .deliverables import drawings, encoded

        [polygons] = drawings(self.scene, None, ("balancing",))
        return Drawing(str(encoded(polygons, ("svg",))[f"{polygons.stem}.svg"]))

    def _repr_svg_(self) -> str:
        return self.drawing.svg


@dataclass(frozen=True)
class VibrationResponse:
    """The machine's steady vibration on its mounts as a run works it out: the numbers ``results.json`` writes and
    its plots of the magnification and the transmissibility."""

    scene: Scene = dataclasses.field(repr=False)

    def __repr__(self) -> str:
        found = self.response
        return (f"<VibrationResponse of {self.scene.title!r}: X = {found.amplitude:.4g} m, "
                f"TR = {found.transmissibility:.4g} at ω/ωn = {found.frequency_ratio:.4g}>")

    @cached_property
    def response(self) -> Response:
        """The record the run works from (SI, the lag ``phase`` in radians): ``amplitude``, ``transmissibility``,
        ``transmitted_force``, ``natural_frequency``, ``frequency_ratio``, ``magnification``, the isolation's, the
        base's (``base``) and both together (``combined``) where the scene has them."""
        from .vibration import steady_state

        assert self.scene.vibration is not None
        return steady_state(self.scene.vibration)

    @property
    def results(self) -> dict:
        """``results.json``'s ``vibration``, as the run writes it (angles in degrees, speeds also in rpm); a copy
        of the script's own, which the next ask hands out as the run wrote it again."""
        return copy.deepcopy(self._document)

    @cached_property
    def _document(self) -> dict:
        from .deliverables import vibration_document

        return vibration_document(self.scene)

    @cached_property
    def _plots(self) -> dict[str, str]:
        from .deliverables import vibration_figures

        return vibration_figures(self.scene)

    @property
    def magnification_plot(self) -> Drawing:
        """M·X/(m·e) against ω/ωn, the machine marked on its curve: the run's ``vibration_magnification.svg``."""
        return Drawing(self._plots["vibration_magnification.svg"], png_dpi=PLOT_DPI)

    @property
    def transmissibility_plot(self) -> Drawing:
        """TR against ω/ωn, the machine and the isolation's design marked: the run's
        ``vibration_transmissibility.svg``."""
        return Drawing(self._plots["vibration_transmissibility.svg"], png_dpi=PLOT_DPI)


__all__ = ["Drawing", "PositionPlans", "RotorBalancing", "VibrationResponse", "plan"]
